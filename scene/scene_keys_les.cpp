// Scene keys of the subgrid-scale model (les/, issue 4) and their reader les_setup.
#include "scene/scene_keys_les.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <ctime>
#include <stdexcept>

#include "analysis/sgs_energy_field.hpp"
#include "core/thread_cpu_time.hpp"
#include "les/pope_estimate.hpp"
#include "les/sgs_energy.hpp"
#include "les/subgrid_viscosity.hpp"
#include "scene/scene_keys.hpp"

namespace valsalva::scene {

void declare_les_keys(Schema& s) {
  s.section("les", "Large Eddy Simulation: the subgrid-scale eddy viscosity added to nu.");
  s.choice("les.model", les::sgs_kind_names())
      .def("none")
      .unit_of("-")
      .doc(
          "Subgrid model, nu_sgs from the nodal velocity gradient with Delta = cube root of the "
          "dual volume; none = laminar (no subgrid viscosity is computed)");
  s.real("les.constant")
      .def(0.0)
      .at_least(0)
      .note("0 = the model's default")
      .unit_of("-")
      .doc(
          "Model constant; 0 takes the default: sigma 1.35 (Nicoud et al., Phys. Fluids 23, "
          "085106, 2011), wale 0.5 (Nicoud & Ducros, Flow Turbul. Combust. 62, 1999: "
          "C_w^2 = 10.6 C_s^2), smagorinsky 0.17 (Lilly 1967 with C_K = 1.5)");
  s.choice("les.update", les::sgs_update_names())
      .def("step")
      .unit_of("-")
      .doc(
          "When nu_sgs is computed: step = once per time step from v^n, held over the 4 RK "
          "stages (4x cheaper: 6-7 % of a step instead of 20-23 % at 48^3; the TGV Re 1600 peak "
          "-dE/dt at 64^3 moves by 0.65 % and the CBC resolved energy by 0.2-0.4 %, "
          "validation/tgv_les and bench_les_cost); stage = at every RK stage");
  s.real("les.integral_length")
      .def(0.0)
      .at_least(0)
      .note("0 = not given")
      .unit_of("m")
      .doc(
          "Integral length scale L of the turbulence for the output field pope_sgs_fraction "
          "(Pope's estimate of the subgrid share of the turbulent energy; a resolved LES has "
          "<= 0.2), e.g. the jet or vessel radius downstream of a valve; needed by that field");
}

struct LesSetup::Shared {
  les::SubgridViscosity model;
  double nu = 0;
  bool energy_fraction = false;             // output.fields has sgs_energy_fraction
  const flow::ScalarField* last = nullptr;  // the solver's nu_sgs array, filled last
  flow::ScalarField ratio, resolved, fraction;
  flow::ScalarField pope;  // pope_sgs_fraction (from the mesh alone), empty when not asked
  const mesh::LocalMesh* local = nullptr;
  double cpu_seconds = 0;  // thread CPU time inside the model, all calls
};

double LesSetup::cpu_seconds() const {
  return shared ? shared->cpu_seconds : 0.0;
}

void LesSetup::add_fields(io::FieldSet& set, double time, const flow::VectorField& velocity,
                          const std::vector<analysis::PhaseStatistics>& statistics) const {
  if (!shared) return;
  auto& sh = *shared;
  const double scale = sh.nu > 0 ? 1.0 / sh.nu : 1.0;
  sh.ratio.assign(sh.model.size(), 0.0);  // zero before the first stage (t = 0)
  if (sh.last)
    for (std::size_t i = 0; i < sh.ratio.size(); ++i) sh.ratio[i] = (*sh.last)[i] * scale;
  set.scalars.emplace_back(sh.nu > 0 ? "nu_sgs_over_nu" : "nu_sgs", &sh.ratio);
  if (!sh.pope.empty()) set.scalars.emplace_back("pope_sgs_fraction", &sh.pope);
  if (!sh.energy_fraction) return;
  analysis::resolved_turbulent_energy(*sh.local, velocity, statistics, time, sh.resolved);
  sh.fraction.assign(sh.resolved.size(), 0.0);
  const std::vector<double> zero(sh.last ? 0 : sh.resolved.size(), 0.0);
  les::subgrid_energy_fraction(sh.last ? std::span<const double>(*sh.last) : zero,
                               sh.model.filter_width(), sh.resolved, sh.fraction);
  set.scalars.emplace_back("sgs_energy_fraction", &sh.fraction);
}

namespace {

bool wants_field(const Scene& scene, const char* name) {
  const auto fields = scene.get<std::vector<std::string>>("output.fields");
  return std::find(fields.begin(), fields.end(), name) != fields.end();
}

}  // namespace

void check_les_scene(const Scene& scene) {
  for (const char* field : {"sgs_energy_fraction", "pope_sgs_fraction"})
    if (scene.get<std::string>("les.model") == "none" && wants_field(scene, field))
      throw scene.error("output.fields", fmt::format("{} needs a subgrid model", field),
                        fmt::format("les.model = sigma, wale or smagorinsky, or drop {}", field));
  if (wants_field(scene, "pope_sgs_fraction") && !(scene.get<double>("les.integral_length") > 0))
    throw scene.error("les.integral_length",
                      "pope_sgs_fraction in output.fields needs the integral length scale",
                      "les.integral_length = L > 0 in m");
}

void LesSetup::resume(const flow::ScalarField& nu_sgs) const {
  if (shared && !nu_sgs.empty()) shared->last = &nu_sgs;
}

LesSetup les_setup(const Scene& scene, const mesh::LocalMesh& local) {
  check_les_scene(scene);
  LesSetup out;
  out.model = les::parse_sgs_kind(scene.get<std::string>("les.model"));
  if (out.model == les::SgsKind::none) return out;
  const bool fraction = wants_field(scene, "sgs_energy_fraction");
  const double c = scene.get<double>("les.constant");
  try {
    out.shared = std::make_shared<LesSetup::Shared>(LesSetup::Shared{
        les::SubgridViscosity(out.model, c, local.h,
                              les::parse_sgs_update(scene.get<std::string>("les.update"))),
        scene.get<double>("flow.viscosity") / scene.get<double>("flow.density"),
        fraction,
        nullptr,
        {},
        {},
        {},
        {},
        &local});
  } catch (const std::invalid_argument& e) {
    throw scene.error("les.constant", e.what(), "a finite value > 0, or 0 for the default");
  }
  out.constant = out.shared->model.model().constant;
  if (wants_field(scene, "pope_sgs_fraction")) {
    const double L = scene.get<double>("les.integral_length");
    for (double delta : out.shared->model.filter_width())
      out.shared->pope.push_back(les::pope_subgrid_fraction(delta, L));
  }
  out.subgrid_viscosity = [sh = out.shared](int stage, const flow::TensorField& grad,
                                            flow::ScalarField& nu_sgs) {
    const double t0 = core::thread_cpu_seconds();
    sh->model(stage, grad, nu_sgs);
    sh->cpu_seconds += core::thread_cpu_seconds() - t0;
    sh->last = &nu_sgs;
  };
  return out;
}

}  // namespace valsalva::scene
