// [forcing]: a prescribed body force (flow/body_forcing.hpp) or one that holds a flow rate
// (flow/flow_rate_control.hpp), declared and read here.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "io/waveform_table.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_keys_flow.hpp"

namespace valsalva::scene {

void declare_forcing_keys(Schema& s) {
  s.section("forcing",
            "A prescribed body-force density, for flows driven without inlets (periodic boxes, "
            "pipes and channels); added to the force of immersed structures. The uniform and "
            "flow_rate forces go into log.csv (force_x, force_y, force_z; flow_rate_target).");
  s.choice("forcing.type", {"none", "uniform", "kolmogorov", "flow_rate"})
      .def("none")
      .unit_of("-")
      .doc(
          "none; uniform = the force density `force` everywhere (a mean pressure gradient G is "
          "force = -G), constant or following `waveform`; kolmogorov = force sin(2 pi s / "
          "wavelength), s = x . across, its discrete volume mean removed so that a periodic box "
          "gains no net momentum; flow_rate = a uniform force along `direction` adjusted every "
          "step so that the flux through [section.<section>] holds `flow_rate` (constant flow "
          "rate drive of Kim, Moin & Moser 1987; domains closed by walls and periodic pairs)");
  s.real3("forcing.force")
      .required()
      .unit_of("N/m3")
      .doc("Force density (uniform: its mean, or its scale with a table; kolmogorov: amplitude)");
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

  s.choice("forcing.waveform", {"constant", "sine", "table"})
      .def("constant")
      .unit_of("-")
      .doc(
          "uniform: force (constant), force + force_amplitude sin(2 pi t / period + phase) "
          "(sine) or force s(t) with s from `file` (table); flow_rate: the target Q(t) = "
          "flow_rate (constant), flow_rate + flow_rate_amplitude sin(2 pi t / period + phase) "
          "(sine) or Q from `file` (table)");
  s.when("forcing.waveform", "forcing.type", {"uniform", "flow_rate"});
  s.real3("forcing.force_amplitude")
      .required()
      .unit_of("N/m3")
      .doc("uniform, sine: amplitude of the force density's oscillation about `force`");
  s.when("forcing.force_amplitude", "forcing.type", {"uniform"});
  s.when("forcing.force_amplitude", "forcing.waveform", {"sine"});
  s.real("forcing.period").required().above(0).unit_of("s").doc("sine: the period");
  s.when("forcing.period", "forcing.type", {"uniform", "flow_rate"});
  s.when("forcing.period", "forcing.waveform", {"sine"});
  s.real("forcing.phase").def(0.0).unit_of("rad").doc("sine: the phase at t = 0");
  s.when("forcing.phase", "forcing.type", {"uniform", "flow_rate"});
  s.when("forcing.phase", "forcing.waveform", {"sine"});
  s.string("forcing.file")
      .required()
      .unit_of("-")
      .doc(
          "table: CSV rows 't, value' (s and, for uniform, the dimensionless factor of `force`; "
          "for flow_rate, Q in m3/s), relative to the scene file; one period, repeated");
  s.when("forcing.file", "forcing.type", {"uniform", "flow_rate"});
  s.when("forcing.file", "forcing.waveform", {"table"});

  s.real3("forcing.direction")
      .required()
      .unit_of("-")
      .doc("flow_rate: the direction of the force (normalised); the flux is the section's");
  s.when("forcing.direction", "forcing.type", {"flow_rate"});
  s.string("forcing.section")
      .required()
      .unit_of("-")
      .doc("flow_rate: the name of the [section.<name>] whose flux is held at the target");
  s.when("forcing.section", "forcing.type", {"flow_rate"});
  s.real("forcing.flow_rate")
      .required()
      .unit_of("m3/s")
      .doc("flow_rate: the target flux through the section (constant; sine: its mean)");
  s.when("forcing.flow_rate", "forcing.type", {"flow_rate"});
  s.when("forcing.flow_rate", "forcing.waveform", {"constant", "sine"});
  s.real("forcing.flow_rate_amplitude")
      .required()
      .unit_of("m3/s")
      .doc("flow_rate, sine: amplitude of the target's oscillation");
  s.when("forcing.flow_rate_amplitude", "forcing.type", {"flow_rate"});
  s.when("forcing.flow_rate_amplitude", "forcing.waveform", {"sine"});
}

namespace {

Eigen::Vector3d finite_vector(const Scene& scene, const std::string& key) {
  const auto v = scene.get<std::array<double, 3>>(key);
  const Eigen::Vector3d x(v[0], v[1], v[2]);
  if (!x.allFinite()) throw scene.error(key, "the vector must be finite");
  return x;
}

flow::Waveform table(const Scene& scene) {
  try {
    auto factor = io::read_waveform_table(scene.path("forcing.file"));
    io::check_table_wrap(factor, scene.get<double>("time.end"),
                         scene.path("forcing.file").string());
    return factor;
  } catch (const std::exception& e) {
    throw scene.error("forcing.file", e.what());
  }
}

}  // namespace

flow::ForcingSpec read_forcing(const Scene& scene) {
  flow::ForcingSpec f;
  const auto type = scene.get<std::string>("forcing.type");
  if (type == "none") return f;
  f.type = type == "uniform"      ? flow::ForcingSpec::Type::uniform
           : type == "kolmogorov" ? flow::ForcingSpec::Type::kolmogorov
                                  : flow::ForcingSpec::Type::flow_rate;
  if (f.type == flow::ForcingSpec::Type::kolmogorov) {
    f.force = finite_vector(scene, "forcing.force");
    f.across = finite_vector(scene, "forcing.across");
    if (!(f.across.norm() > 0))
      throw scene.error("forcing.across", "the direction must be a non-zero finite vector");
    f.wavelength = scene.get<double>("forcing.wavelength");
    return f;
  }
  const auto waveform = scene.get<std::string>("forcing.waveform");
  const auto kind = waveform == "sine"    ? flow::Waveform::Kind::sine
                    : waveform == "table" ? flow::Waveform::Kind::table
                                          : flow::Waveform::Kind::constant;
  if (f.type == flow::ForcingSpec::Type::uniform) {
    f.force = finite_vector(scene, "forcing.force");
    f.waveform = kind;
    if (kind == flow::Waveform::Kind::sine) {
      f.amplitude = finite_vector(scene, "forcing.force_amplitude");
      f.period = scene.get<double>("forcing.period");
      f.phase = scene.get<double>("forcing.phase");
    } else if (kind == flow::Waveform::Kind::table) {
      f.factor = table(scene);
    }
    return f;
  }
  f.direction = finite_vector(scene, "forcing.direction");
  if (!(f.direction.norm() > 0))
    throw scene.error("forcing.direction", "the direction must be a non-zero vector");
  f.section = scene.get<std::string>("forcing.section");
  const auto names = scene.names("section");
  if (std::find(names.begin(), names.end(), f.section) == names.end())
    throw scene.error("forcing.section", fmt::format("no [section.{}] in the scene", f.section),
                      names.empty() ? std::string("a [section.<name>] table's name")
                                    : fmt::format("one of: {}", fmt::join(names, ", ")));
  if (kind == flow::Waveform::Kind::table) {
    f.flow_rate = table(scene);
  } else {
    f.flow_rate.kind = kind;
    f.flow_rate.mean = scene.get<double>("forcing.flow_rate");
    if (kind == flow::Waveform::Kind::sine) {
      f.flow_rate.amplitude = scene.get<double>("forcing.flow_rate_amplitude");
      f.flow_rate.period = scene.get<double>("forcing.period");
      f.flow_rate.phase = scene.get<double>("forcing.phase");
    }
  }
  return f;
}

void check_forcing(const Scene& scene, const std::vector<flow::BoundarySpec>& boundary) {
  if (scene.get<std::string>("forcing.type") != "flow_rate") return;
  for (const auto& b : boundary)
    if (b.type != flow::BoundaryType::wall && b.type != flow::BoundaryType::slip)
      throw scene.error("forcing.type",
                        fmt::format("flow_rate drives a domain closed by walls and periodic "
                                    "pairs, but boundary patch '{}' lets flow in or out",
                                    b.patch),
                        "a scene whose [boundary.<patch>] are all walls or slip walls");
}

}  // namespace valsalva::scene
