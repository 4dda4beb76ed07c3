// Reproducing-kernel (RKPM) correction of a discrete Dirac kernel with a linear basis
// (W. K. Liu, S. Jun, Y. F. Zhang, Int. J. Numer. Meth. Fluids 20:1081-1106, 1995; A. Pinelli,
// I. Z. Naqavi, U. Piomelli, J. Favier, J. Comput. Phys. 229:9073-9091, 2010; J. Siguenza,
// S. Mendez, D. Ambard et al., J. Comput. Phys. 322:723-746, 2016):
//   phi(x_j, X) = H(0)^T M^{-1} H(x_j - X) psi(x_j - X),  H(y) = [1, y1, y2, y3],
//   M = sum_j H(x_j - X) H(x_j - X)^T psi(x_j - X) V_j.
// Then sum_j phi_j V_j = 1 and sum_j (x_j - X) phi_j V_j = 0 to round-off on any node cloud,
// including a support cut by a wall. H is scaled by the support radius (it does not change phi)
// so that the reciprocal condition number of M measures the geometry, not the units.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <vector>

namespace valsalva::ibm {

struct RkpmResult {
  // Reciprocal condition number of the scaled M in the 1-norm, 1 / (|M|_1 |M^-1|_1): between 1/4
  // and 1 times the smallest/largest eigenvalue ratio; 0 when M is not positive definite.
  double rcond = 0;
  bool ok = false;  // rcond >= the threshold passed in
};

// `offset[j]` = x_j - X, `psi[j]` the base kernel at offset[j], `volume[j]` = V_j. Writes the
// corrected kernel values into `phi` (same length) when the moment matrix is well conditioned.
RkpmResult rkpm_correct(std::span<const Eigen::Vector3d> offset, std::span<const double> psi,
                        std::span<const double> volume, double length_scale, double min_rcond,
                        std::span<double> phi);

}  // namespace valsalva::ibm
