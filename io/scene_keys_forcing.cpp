// [forcing]: a prescribed body force (flow/body_forcing.hpp), declared and read here.
#include <array>
#include <cmath>

#include "io/scene_keys.hpp"
#include "io/scene_keys_flow.hpp"

namespace valsalva::io {

void declare_forcing_keys(Schema& s) {
  s.section("forcing",
            "A prescribed body-force density, for flows driven without inlets (periodic boxes, "
            "pipes and channels); added to the force of immersed structures.");
  s.choice("forcing.type", {"none", "uniform", "kolmogorov"})
      .def("none")
      .unit_of("-")
      .doc(
          "none; uniform = the force density `force` everywhere (a mean pressure gradient G is "
          "force = -G); kolmogorov = force sin(2 pi s / wavelength), s = x . across, its "
          "discrete volume mean removed so that a periodic box gains no net momentum");
  s.real3("forcing.force")
      .required()
      .unit_of("N/m3")
      .doc("Force density (kolmogorov: its amplitude and direction)");
  s.when("forcing.force", "forcing.type", {"uniform", "kolmogorov"});
  s.real3("forcing.across")
      .def(std::array<double, 3>{0.0, 1.0, 0.0})
      .unit_of("-")
      .doc("kolmogorov: the direction along which the force varies (normalised)");
  s.when("forcing.across", "forcing.type", {"kolmogorov"});
  s.real("forcing.wavelength")
      .required()
      .above(0)
      .unit_of("m")
      .doc("kolmogorov: the period of the force along `across`");
  s.when("forcing.wavelength", "forcing.type", {"kolmogorov"});
}

flow::ForcingSpec read_forcing(const Scene& scene) {
  flow::ForcingSpec f;
  const auto type = scene.get<std::string>("forcing.type");
  if (type == "none") return f;
  f.type =
      type == "uniform" ? flow::ForcingSpec::Type::uniform : flow::ForcingSpec::Type::kolmogorov;
  const auto v = scene.get<std::array<double, 3>>("forcing.force");
  f.force = Eigen::Vector3d(v[0], v[1], v[2]);
  if (!f.force.allFinite()) throw scene.error("forcing.force", "the force density must be finite");
  if (f.type == flow::ForcingSpec::Type::kolmogorov) {
    const auto a = scene.get<std::array<double, 3>>("forcing.across");
    f.across = Eigen::Vector3d(a[0], a[1], a[2]);
    if (!(f.across.norm() > 0) || !f.across.allFinite())
      throw scene.error("forcing.across", "the direction must be a non-zero finite vector");
    f.wavelength = scene.get<double>("forcing.wavelength");
  }
  return f;
}

}  // namespace valsalva::io
