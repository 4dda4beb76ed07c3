// Pointwise subgrid-scale eddy-viscosity kernels nu_sgs(g, Delta), g_ij = du_i/dx_j, Delta the
// filter width [m]; results in m^2/s. Small pure functions; the loops live in sgs_model.cpp.
//
// - Sigma: Nicoud, Toda, Cabrit, Bose, Lee, Phys. Fluids 23, 085106 (2011), eq. (14):
//     nu = (C_sigma Delta)^2 sigma3 (sigma1 - sigma2)(sigma2 - sigma3) / sigma1^2.
// - WALE: Nicoud & Ducros, Flow Turbul. Combust. 62, 183-200 (1999), eqs. (10), (13):
//     Sd = 1/2 (g^2 + g^2^T) - 1/3 tr(g^2) I,
//     nu = (C_w Delta)^2 (Sd:Sd)^(3/2) / ((S:S)^(5/2) + (Sd:Sd)^(5/4)).
// - Smagorinsky: Smagorinsky, Mon. Weather Rev. 91, 99-164 (1963):
//     nu = (C_s Delta)^2 sqrt(2 S:S).
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "les/singular_values.hpp"

namespace valsalva::les {

// Sigma differential operator D_sigma [1/s]; zero for 2D flow, pure shear, solid rotation,
// axisymmetric and isotropic expansion, O(y^3) at a wall (Nicoud et al. 2011, Sec. II).
inline double sigma_operator(const Eigen::Matrix3d& g) {
  const Eigen::Vector3d s = singular_values(g);
  if (s(0) == 0.0) return 0.0;  // (a NaN gradient propagates)
  return s(2) * (s(0) - s(1)) * (s(1) - s(2)) / (s(0) * s(0));
}

inline double sigma_nu(const Eigen::Matrix3d& g, double delta, double c_sigma) {
  const double cd = c_sigma * delta;
  return cd * cd * sigma_operator(g);
}

// WALE operator (Sd:Sd)^(3/2) / ((S:S)^(5/2) + (Sd:Sd)^(5/4)) [1/s].
inline double wale_operator(const Eigen::Matrix3d& g) {
  const Eigen::Matrix3d S = 0.5 * (g + g.transpose());
  const Eigen::Matrix3d g2 = g * g;
  Eigen::Matrix3d Sd = 0.5 * (g2 + g2.transpose());
  Sd.diagonal().array() -= g2.trace() / 3.0;
  const double sdsd = Sd.squaredNorm();
  const double ss = S.squaredNorm();
  // Powers 3/2, 5/2, 5/4 through square roots (std::pow is several times slower).
  const double r = std::sqrt(sdsd);
  const double den = ss * ss * std::sqrt(ss) + sdsd * std::sqrt(r);
  return den == 0.0 ? 0.0 : sdsd * r / den;  // zero gradient -> 0; NaN propagates
}

inline double wale_nu(const Eigen::Matrix3d& g, double delta, double c_w) {
  const double cd = c_w * delta;
  return cd * cd * wale_operator(g);
}

// |S| = sqrt(2 S:S) [1/s].
inline double strain_rate_magnitude(const Eigen::Matrix3d& g) {
  return std::sqrt(2.0 * (0.5 * (g + g.transpose())).squaredNorm());
}

inline double smagorinsky_nu(const Eigen::Matrix3d& g, double delta, double c_s) {
  const double cd = c_s * delta;
  return cd * cd * strain_rate_magnitude(g);
}

}  // namespace valsalva::les
