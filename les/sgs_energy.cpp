// Yoshizawa subgrid energy and the subgrid energy fraction; see sgs_energy.hpp.
#include "les/sgs_energy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace valsalva::les {

double yoshizawa_sgs_energy(double nu_sgs, double delta, double c_k) {
  if (!(nu_sgs >= 0.0) || !(delta > 0.0) || !(c_k > 0.0) || !std::isfinite(nu_sgs))
    throw std::invalid_argument(fmt::format(
        "yoshizawa_sgs_energy: nu_sgs = {} must be >= 0 and finite, Delta = {} and C_k = {} > 0",
        nu_sgs, delta, c_k));
  const double q = nu_sgs / (c_k * delta);
  return q * q;
}

double subgrid_energy_fraction(double k_sgs, double k_resolved) {
  const double total = k_sgs + k_resolved;
  return total > 0.0 ? k_sgs / total : 0.0;
}

void subgrid_energy_fraction(std::span<const double> nu_sgs, std::span<const double> delta,
                             std::span<const double> k_resolved, std::span<double> out,
                             double c_k) {
  if (delta.size() != nu_sgs.size() || k_resolved.size() != nu_sgs.size() ||
      out.size() != nu_sgs.size())
    throw std::invalid_argument(fmt::format(
        "subgrid_energy_fraction: {} nu_sgs, {} filter widths, {} resolved energies, {} outputs",
        nu_sgs.size(), delta.size(), k_resolved.size(), out.size()));
  for (std::size_t i = 0; i < nu_sgs.size(); ++i)
    out[i] = subgrid_energy_fraction(yoshizawa_sgs_energy(nu_sgs[i], delta[i], c_k), k_resolved[i]);
}

}  // namespace valsalva::les
