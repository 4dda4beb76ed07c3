#include "ibm/rkpm.hpp"

#include <cassert>

namespace valsalva::ibm {

RkpmResult rkpm_correct(std::span<const Eigen::Vector3d> offset, std::span<const double> psi,
                        std::span<const double> volume, double length_scale, double min_rcond,
                        std::span<double> phi) {
  assert(offset.size() == psi.size() && psi.size() == volume.size() && phi.size() == psi.size());
  const double inv = 1.0 / length_scale;
  auto basis = [&](const Eigen::Vector3d& y) {
    return Eigen::Vector4d(1.0, y.x() * inv, y.y() * inv, y.z() * inv);
  };
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  for (std::size_t j = 0; j < offset.size(); ++j) {
    const Eigen::Vector4d hj = basis(offset[j]);
    m.noalias() += (psi[j] * volume[j]) * hj * hj.transpose();
  }
  RkpmResult result;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(m, Eigen::EigenvaluesOnly);
  const double largest = eig.eigenvalues().maxCoeff();
  result.rcond = largest > 0 ? eig.eigenvalues().minCoeff() / largest : 0.0;
  result.ok = result.rcond >= min_rcond;
  if (!result.ok) return result;
  // b = M^{-1} H(0); full pivoting keeps the residual of M b = e0 at round-off.
  const Eigen::Vector4d b = m.fullPivLu().solve(Eigen::Vector4d::UnitX());
  for (std::size_t j = 0; j < offset.size(); ++j) phi[j] = b.dot(basis(offset[j])) * psi[j];
  return result;
}

}  // namespace valsalva::ibm
