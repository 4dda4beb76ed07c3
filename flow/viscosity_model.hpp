// Generalised-Newtonian viscosity laws: the apparent dynamic viscosity mu(gamma_dot) of a fluid
// whose stress is 2 mu(gamma_dot) S, with the shear rate gamma_dot = sqrt(2 S:S) from the
// strain-rate tensor S = (grad u + grad u^T) / 2 (Bird, Armstrong & Hassager, Dynamics of
// Polymeric Liquids vol. 1, 2nd ed., 1987, ch. 4). The laws:
// - Carreau-Yasuda: mu = mu_inf + (mu_0 - mu_inf) (1 + (lambda gamma_dot)^a)^((n - 1) / a)
//   (Yasuda, Armstrong & Cohen, Rheol. Acta 20, 1981); the scene defaults are Cho & Kensey's
//   blood values (Biorheology 28, 241-262, 1991): mu_0 = 0.056 Pa s, mu_inf = 0.00345 Pa s,
//   lambda = 3.313 s, a = 2, n = 0.3568.
// - Casson: sqrt(tau) = sqrt(tau_y) + sqrt(mu_p gamma_dot) beyond the yield stress tau_y, rigid
//   below (Casson 1959; for blood e.g. Fung, Biomechanics: Mechanical Properties of Living
//   Tissues, 2nd ed., 1993, ch. 3), i.e. mu = (sqrt(mu_p) + sqrt(tau_y / gamma_dot))^2,
//   regularised after Papanastasiou (J. Rheol. 31, 385-404, 1987) by replacing tau_y / gamma_dot
//   with tau_y (1 - exp(-m gamma_dot)) / gamma_dot: finite at rest, mu(0) = (sqrt(mu_p) +
//   sqrt(tau_y m))^2, and within a relative exp(-m gamma_dot) of Casson's yield term where the
//   fluid flows. m (s) is the documented regularisation parameter.
// - Power law: mu = K max(gamma_dot, gamma_min)^(n - 1), for verification only (its viscosity
//   is infinite (n < 1) or zero (n > 1) at rest without the floor gamma_min). With n < 1 the
//   floor caps the viscosity at K gamma_min^(n - 1): the fluid is Newtonian at that viscosity
//   wherever gamma_dot < gamma_min (in a pipe driven by G = -dp/dz: r < 2 K gamma_min^n / G).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>

namespace valsalva::flow {

enum class ViscosityLaw { newtonian, carreau_yasuda, casson, power_law };

struct ViscosityModel {
  ViscosityLaw law = ViscosityLaw::newtonian;
  double mu = 0;  // Pa s: newtonian
  // carreau_yasuda
  double mu_0 = 0, mu_inf = 0;  // Pa s
  double lambda = 0;            // s
  double a = 2, n = 1;          // -  (n is also the power-law index)
  // casson
  double yield_stress = 0;       // Pa
  double plastic_viscosity = 0;  // Pa s
  double regularisation = 0;     // s: Papanastasiou's m
  // power_law
  double consistency = 0;     // K, Pa s^n
  double shear_rate_min = 0;  // 1/s: gamma_min
};

// What is wrong with a model's parameters, if anything: the parameter's name (as the field of
// ViscosityModel) and why. Negative or non-finite values, mu_0 < mu_inf, n <= 0, a <= 0, a
// yield stress without regularisation, a power law without a positive shear-rate floor.
struct ViscosityModelProblem {
  std::string parameter, message, accepted;
};
std::optional<ViscosityModelProblem> viscosity_model_problem(const ViscosityModel& model);

// gamma_dot = sqrt(2 S:S) of a velocity gradient (i, j) = d u_i / d x_j, 1/s.
inline double shear_rate(const Eigen::Matrix3d& grad) {
  const Eigen::Matrix3d s = 0.5 * (grad + grad.transpose());
  return std::sqrt(2.0 * s.squaredNorm());
}

// The apparent dynamic viscosity at shear rate gamma_dot >= 0, Pa s (a pure function).
double apparent_viscosity(const ViscosityModel& model, double gamma_dot);

// The infimum of mu(gamma_dot) over all shear rates, Pa s: Carreau-Yasuda mu_inf (n < 1) or
// mu_0 (n >= 1), Casson mu_p, a power law K gamma_min^(n - 1) (n >= 1) or 0 (n < 1: it thins
// without bound). The viscous time-step bound of the fluid is at most h^2 / (this / rho).
double lowest_viscosity(const ViscosityModel& model);

// The viscosity the explicit time step's Fourier bound takes at every node, Pa s, or 0 when each
// node's own mu(gamma_dot) sets it: the cap K gamma_min^(n - 1) of a power law with n < 1, the
// largest viscosity that law can produce. The cap is reached wherever the shear rate drops below
// gamma_min (at rest, on a pipe's axis, where the flow reverses), and the nodal viscosity is
// re-evaluated at every RK stage, so it can rise to the cap within a step: a bound from the
// step's start would not hold at its stages. With the cap the viscous bound is
// dt <= time.fourier h^2 rho / (K gamma_min^(n - 1)): the step count grows as gamma_min^(n - 1).
double viscosity_cap(const ViscosityModel& model);

std::string viscosity_law_name(ViscosityLaw law);

}  // namespace valsalva::flow
