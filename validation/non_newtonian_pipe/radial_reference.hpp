// Steady fully developed pipe flow of a generalised-Newtonian fluid, computed in 1D, and the
// classical closed forms it is checked against. In a straight pipe driven by G = -dp/dz the
// momentum balance of a cylinder of radius r gives the shear stress tau(r) = G r / 2 whatever
// the viscosity law (Bird, Stewart & Lightfoot, Transport Phenomena, 2nd ed., 2002, sec. 2.3 and
// ex. 8.3-1), so the radial ODE du/dr = -gamma_dot(r) has its right-hand side from the flow
// curve alone: mu(gamma_dot) gamma_dot = G r / 2, solved for gamma_dot by bisection (the flow
// curves of flow/viscosity_model.hpp increase with gamma_dot), then integrated inwards from
// u(R) = 0 with the trapezoidal rule on a fine uniform grid.
#pragma once

#include <vector>

#include "flow/viscosity_model.hpp"

namespace valsalva::validation {

struct RadialProfile {
  double radius = 0;
  std::vector<double> u;      // m/s at r_i = radius i / (size - 1)
  double flow_rate = 0;       // m^3/s, 2 pi int u r dr (trapezoidal)
  double at(double r) const;  // linear interpolation, r in [0, radius]
};

// `points` >= 2 grid points from the axis to the wall.
RadialProfile steady_pipe_profile(const flow::ViscosityModel& model, double pressure_gradient,
                                  double radius, int points);

// Power-law fluid tau = K gamma_dot^n (no floor): u(r) = n/(n+1) (G/(2K))^(1/n) (R^(1+1/n) -
// r^(1+1/n)) (Bird, Stewart & Lightfoot, Transport Phenomena, 2nd ed., problem 2B.6 / ex. 8.3-1).
double power_law_pipe_velocity(double consistency, double n, double pressure_gradient,
                               double radius, double r);
// Its flow rate 2 pi int u r dr = pi n / (3n+1) (G/(2K))^(1/n) R^(3+1/n).
double power_law_pipe_flow_rate(double consistency, double n, double pressure_gradient,
                                double radius);

// Ideal Casson fluid (unregularised): plug of radius r_p = 2 tau_y / G moving at u(r_p); outside
// it u(r) = [G/4 (R^2 - r^2) - 4/3 sqrt(tau_y G / 2) (R^1.5 - r^1.5) + tau_y (R - r)] / mu_p
// (from sqrt(tau) = sqrt(tau_y) + sqrt(mu_p gamma_dot) with tau = G r / 2), and
// Q = pi R^4 G / (8 mu_p) [1 - 16/7 sqrt(xi) + 4/3 xi - xi^4 / 21], xi = r_p / R (Fung,
// Biomechanics: Mechanical Properties of Living Tissues, 2nd ed., 1993, ch. 3).
double casson_pipe_velocity(double yield_stress, double plastic_viscosity, double pressure_gradient,
                            double radius, double r);
double casson_pipe_flow_rate(double yield_stress, double plastic_viscosity,
                             double pressure_gradient, double radius);

}  // namespace valsalva::validation
