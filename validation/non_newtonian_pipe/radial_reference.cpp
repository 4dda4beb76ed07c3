// Steady generalised-Newtonian pipe flow in 1D; see radial_reference.hpp.
#include "validation/non_newtonian_pipe/radial_reference.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace valsalva::validation {

namespace {
// gamma_dot with mu(gamma_dot) gamma_dot = tau, by bisection in log(gamma_dot) to round-off.
double shear_rate_at_stress(const flow::ViscosityModel& model, double tau) {
  if (tau <= 0) return 0;
  double lo = 1e-30, hi = 1.0;
  while (flow::apparent_viscosity(model, hi) * hi < tau) {
    hi *= 2;
    if (hi > 1e30) throw std::runtime_error("steady_pipe_profile: no shear rate for the stress");
  }
  for (int k = 0; k < 200 && hi > lo * (1 + 1e-15); ++k) {
    const double mid = std::sqrt(lo * hi);
    (flow::apparent_viscosity(model, mid) * mid < tau ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}
}  // namespace

double RadialProfile::at(double r) const {
  const double s = std::clamp(r / radius, 0.0, 1.0) * static_cast<double>(u.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(s), u.size() - 2);
  const double w = s - static_cast<double>(i);
  return (1 - w) * u[i] + w * u[i + 1];
}

RadialProfile steady_pipe_profile(const flow::ViscosityModel& model, double pressure_gradient,
                                  double radius, int points) {
  if (points < 2 || !(radius > 0) || !(pressure_gradient > 0))
    throw std::invalid_argument(
        fmt::format("steady_pipe_profile: {} points, radius {:g}, pressure gradient {:g}", points,
                    radius, pressure_gradient));
  RadialProfile p;
  p.radius = radius;
  const auto n = static_cast<std::size_t>(points);
  const double dr = radius / static_cast<double>(n - 1);
  std::vector<double> gamma(n);
  for (std::size_t i = 0; i < n; ++i)
    gamma[i] = shear_rate_at_stress(model, 0.5 * pressure_gradient * dr * static_cast<double>(i));
  p.u.assign(n, 0.0);
  for (std::size_t i = n - 1; i-- > 0;) p.u[i] = p.u[i + 1] + 0.5 * dr * (gamma[i] + gamma[i + 1]);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double r0 = dr * static_cast<double>(i), r1 = r0 + dr;
    p.flow_rate += std::numbers::pi * dr * (p.u[i] * r0 + p.u[i + 1] * r1);
  }
  return p;
}

double power_law_pipe_velocity(double consistency, double n, double pressure_gradient,
                               double radius, double r) {
  const double e = 1 + 1 / n;
  return n / (n + 1) * std::pow(pressure_gradient / (2 * consistency), 1 / n) *
         (std::pow(radius, e) - std::pow(r, e));
}

double power_law_pipe_flow_rate(double consistency, double n, double pressure_gradient,
                                double radius) {
  return std::numbers::pi * n / (3 * n + 1) *
         std::pow(pressure_gradient / (2 * consistency), 1 / n) * std::pow(radius, 3 + 1 / n);
}

double casson_pipe_velocity(double yield_stress, double plastic_viscosity, double pressure_gradient,
                            double radius, double r) {
  const double G = pressure_gradient, R = radius;
  const double x = std::max(r, 2 * yield_stress / G);  // the plug moves at u(r_p)
  return (G / 4 * (R * R - x * x) -
          4.0 / 3.0 * std::sqrt(yield_stress * G / 2) * (std::pow(R, 1.5) - std::pow(x, 1.5)) +
          yield_stress * (R - x)) /
         plastic_viscosity;
}

double casson_pipe_flow_rate(double yield_stress, double plastic_viscosity,
                             double pressure_gradient, double radius) {
  const double xi = 2 * yield_stress / (pressure_gradient * radius);
  return std::numbers::pi * std::pow(radius, 4) * pressure_gradient / (8 * plastic_viscosity) *
         (1 - 16.0 / 7.0 * std::sqrt(xi) + 4.0 / 3.0 * xi - std::pow(xi, 4) / 21);
}

}  // namespace valsalva::validation
