// Scene keys of the fluid's viscosity law (flow/viscosity_model.hpp): flow.viscosity_model and
// one table of parameters per non-Newtonian law; and their reader read_viscosity_model.
#include "scene/scene_keys_rheology.hpp"

#include <fmt/format.h>

#include "scene/scene_keys.hpp"

namespace valsalva::scene {

void declare_rheology_keys(Schema& s) {
  s.choice("flow.viscosity_model", {"newtonian", "carreau_yasuda", "casson", "power_law"})
      .def("newtonian")
      .unit_of("-")
      .doc(
          "Viscosity law (flow/viscosity_model.hpp): newtonian = flow.viscosity; carreau_yasuda, "
          "casson (Papanastasiou-regularised) and power_law (for verification) give an apparent "
          "viscosity mu(gamma_dot) per node from the shear rate gamma_dot = sqrt(2 S:S) of each "
          "RK stage's velocity, in the full-stress viscous term (plus nu_sgs with [les]); the "
          "time step's Fourier bound uses each node's viscosity, [wall_shear] the nodal viscosity "
          "of the sampled velocity, the 1e9-step rule of flow.density the law's lowest viscosity "
          "over all shear rates (a power law with n < 1: its cap, which its Fourier bound takes at "
          "every "
          "node), and flow.viscosity is not used "
          "(except by initial.womersley's profile); initial.type = taylor_green reports no error "
          "against the Newtonian vortex");

  const std::string cy = "flow.carreau_yasuda";
  s.section(cy,
            "Carreau-Yasuda: mu = mu_inf + (mu_0 - mu_inf) (1 + (lambda gamma_dot)^a)^((n-1)/a); "
            "defaults: blood, Cho & Kensey, Biorheology 28, 241-262, 1991");
  s.when(cy, "flow.viscosity_model", {"carreau_yasuda"});
  s.real(cy + ".mu_0").def(0.056).above(0).unit_of("Pa s").doc("Zero-shear viscosity, >= mu_inf");
  s.real(cy + ".mu_inf").def(0.00345).at_least(0).unit_of("Pa s").doc("Infinite-shear viscosity");
  s.real(cy + ".lambda").def(3.313).at_least(0).unit_of("s").doc("Relaxation time");
  s.real(cy + ".a").def(2.0).above(0).unit_of("-").doc("Yasuda exponent (2: the Carreau model)");
  s.real(cy + ".n").def(0.3568).above(0).unit_of("-").doc("Power-law index (< 1: shear thinning)");

  const std::string casson = "flow.casson";
  s.section(casson,
            "Casson fluid, sqrt(tau) = sqrt(tau_y) + sqrt(mu_p gamma_dot), regularised after "
            "Papanastasiou (J. Rheol. 31, 1987): mu = (sqrt(mu_p) + sqrt(tau_y (1 - exp(-m "
            "gamma_dot)) / gamma_dot))^2, finite at rest ((sqrt(mu_p) + sqrt(tau_y m))^2, which "
            "bounds the time step); blood: tau_y of a few mPa, mu_p about 3.5 mPa s (Fung, "
            "Biomechanics, 1993, ch. 3)");
  s.when(casson, "flow.viscosity_model", {"casson"});
  s.real(casson + ".yield_stress").required().at_least(0).unit_of("Pa").doc("Yield stress tau_y");
  s.real(casson + ".plastic_viscosity")
      .required()
      .above(0)
      .unit_of("Pa s")
      .doc("Plastic (Casson) viscosity mu_p");
  s.real(casson + ".regularisation")
      .required()
      .at_least(0)
      .unit_of("s")
      .doc(
          "Papanastasiou's m: the yield term is within exp(-m gamma_dot) of Casson's where the "
          "fluid flows; > 0 with a yield stress");

  const std::string pl = "flow.power_law";
  s.section(pl,
            "Power-law fluid mu = K max(gamma_dot, gamma_min)^(n-1), for verification (no "
            "physiological meaning)");
  s.when(pl, "flow.viscosity_model", {"power_law"});
  s.real(pl + ".consistency").required().above(0).unit_of("Pa s^n").doc("Consistency K");
  s.real(pl + ".n").required().above(0).unit_of("-").doc("Flow index n");
  s.real(pl + ".shear_rate_min")
      .required()
      .above(0)
      .unit_of("1/s")
      .doc(
          "Shear-rate floor gamma_min: n > 1: the viscosity is positive at rest; n < 1: capped at "
          "K gamma_min^(n-1) (Newtonian where gamma_dot < gamma_min; in a pipe driven by G: r < 2 "
          "K gamma_min^n / G), the viscosity every node's Fourier bound takes, so dt <= "
          "time.fourier h^2 rho / (K gamma_min^(n-1)) and the step count grows as "
          "gamma_min^(n-1) (flow/viscosity_model.hpp, viscosity_cap)");
}

flow::ViscosityModel read_viscosity_model(const Scene& scene) {
  flow::ViscosityModel m;
  const auto law = scene.get<std::string>("flow.viscosity_model");
  std::string table;
  if (law == "newtonian") {
    m.mu = scene.get<double>("flow.viscosity");
    return m;
  }
  // flow/operators_order4 has no variable-viscosity term (ProjectionRK4 refuses it too; here
  // the scene is refused before any mesh is built).
  if (scene.get<bool>("flow.fourth_order_operators"))
    throw scene.error("flow.fourth_order_operators",
                      fmt::format("the 4th-order operators have no non-Newtonian viscous term "
                                  "(flow.viscosity_model = {})",
                                  law),
                      "flow.fourth_order_operators = false, or flow.viscosity_model = "
                      "\"newtonian\"");
  if (law == "carreau_yasuda") {
    table = "flow.carreau_yasuda.";
    m.law = flow::ViscosityLaw::carreau_yasuda;
    m.mu_0 = scene.get<double>(table + "mu_0");
    m.mu_inf = scene.get<double>(table + "mu_inf");
    m.lambda = scene.get<double>(table + "lambda");
    m.a = scene.get<double>(table + "a");
    m.n = scene.get<double>(table + "n");
  } else if (law == "casson") {
    table = "flow.casson.";
    m.law = flow::ViscosityLaw::casson;
    m.yield_stress = scene.get<double>(table + "yield_stress");
    m.plastic_viscosity = scene.get<double>(table + "plastic_viscosity");
    m.regularisation = scene.get<double>(table + "regularisation");
  } else {
    table = "flow.power_law.";
    m.law = flow::ViscosityLaw::power_law;
    m.consistency = scene.get<double>(table + "consistency");
    m.n = scene.get<double>(table + "n");
    m.shear_rate_min = scene.get<double>(table + "shear_rate_min");
  }
  if (const auto problem = flow::viscosity_model_problem(m))
    throw scene.error(table + problem->parameter, problem->message, problem->accepted);
  return m;
}

}  // namespace valsalva::scene
