// Field-based estimate of the subgrid share of the turbulent kinetic energy, beside Pope's
// a-priori one (les/pope_estimate.hpp): the subgrid energy from the model's eddy viscosity by
// Yoshizawa's relation nu_sgs = C_k Delta sqrt(k_sgs) (Yoshizawa, Phys. Fluids 29, 2152-2164,
// 1986; C_k = 0.094, the default of OpenFOAM's Smagorinsky and kEqn models), i.e.
//   k_sgs = (nu_sgs / (C_k Delta))^2,   fraction = k_sgs / (k_res + k_sgs),
// with k_res the resolved turbulent energy per unit mass at the node (m^2/s^2). Pope's
// criterion for a well resolved LES: fraction <= 0.2 (Pope, New J. Phys. 6, 35, 2004).
#pragma once

#include <span>

namespace valsalva::les {

inline constexpr double yoshizawa_constant = 0.094;

// k_sgs [m^2/s^2] from nu_sgs [m^2/s] >= 0 and Delta [m] > 0 (std::invalid_argument otherwise).
double yoshizawa_sgs_energy(double nu_sgs, double delta, double c_k = yoshizawa_constant);

// k_sgs / (k_res + k_sgs); 0 when both are 0 (laminar, at rest).
double subgrid_energy_fraction(double k_sgs, double k_resolved);

// Per node: out[i] = subgrid_energy_fraction(yoshizawa_sgs_energy(nu_sgs[i], delta[i]),
// k_resolved[i]); all spans of the same size (std::invalid_argument otherwise).
void subgrid_energy_fraction(std::span<const double> nu_sgs, std::span<const double> delta,
                             std::span<const double> k_resolved, std::span<double> out,
                             double c_k = yoshizawa_constant);

}  // namespace valsalva::les
