// Pope's a-priori estimate of the subgrid share of the turbulent kinetic energy:
//   k_sgs / k = 3/2 C (Delta / (pi L))^(2/3),
// from the inertial-range spectrum E = C eps^(2/3) kappa^(-5/3) integrated beyond the cutoff
// kappa_c = pi / Delta, with eps = k^(3/2) / L (L the integral length scale) and the Kolmogorov
// constant C = 1.5 (Pope, Turbulent Flows, Cambridge 2000, Sec. 6.5 and Ch. 13; Pope, New J.
// Phys. 6, 35, 2004). LES is usually called well resolved when k_sgs / k <= 0.2.
#pragma once

namespace valsalva::les {

inline constexpr double kolmogorov_constant = 1.5;

// k_sgs / k for filter width Delta [m] and integral length L [m] (both > 0).
double pope_subgrid_fraction(double delta, double integral_length, double c = kolmogorov_constant);

// The filter width giving a subgrid fraction f (0 < f): Delta = pi L (f / (3/2 C))^(3/2).
double pope_filter_width(double subgrid_fraction, double integral_length,
                         double c = kolmogorov_constant);

}  // namespace valsalva::les
