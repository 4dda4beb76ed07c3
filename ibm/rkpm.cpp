#include "ibm/rkpm.hpp"

#include "core/check.hpp"

namespace valsalva::ibm {

RkpmResult rkpm_correct(std::span<const Eigen::Vector3d> offset, std::span<const double> psi,
                        std::span<const double> volume, double length_scale, double min_rcond,
                        std::span<double> phi) {
  VALSALVA_DEBUG_CHECK(offset.size() == psi.size() && psi.size() == volume.size() &&
                       phi.size() == psi.size());
  const double inv = 1.0 / length_scale;
  auto basis = [&](const Eigen::Vector3d& y) {
    return Eigen::Vector4d(1.0, y.x() * inv, y.y() * inv, y.z() * inv);
  };
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  for (std::size_t j = 0; j < offset.size(); ++j) {
    const Eigen::Vector4d hj = basis(offset[j]);
    m.noalias() += (psi[j] * volume[j]) * hj * hj.transpose();
  }
  // The 1-norm reciprocal condition number 1 / (|M|_1 |M^-1|_1) from the Cholesky factor: for a
  // symmetric 4x4 matrix it lies between 1/4 and 1 times the eigenvalue ratio, at a fraction of
  // an eigen-solve's cost (locating markers is the costliest part of the coupling).
  RkpmResult result;
  const Eigen::LLT<Eigen::Matrix4d> llt(m);
  if (llt.info() != Eigen::Success) return result;  // not positive definite: rcond 0
  const Eigen::Matrix4d inverse = llt.solve(Eigen::Matrix4d::Identity());
  const double norm = m.cwiseAbs().colwise().sum().maxCoeff();
  const double inverse_norm = inverse.cwiseAbs().colwise().sum().maxCoeff();
  result.rcond = 1.0 / (norm * inverse_norm);
  result.ok = result.rcond >= min_rcond;
  if (!result.ok) return result;
  const Eigen::Vector4d b = inverse.col(0);  // M^{-1} H(0)
  for (std::size_t j = 0; j < offset.size(); ++j) phi[j] = b.dot(basis(offset[j])) * psi[j];
  return result;
}

}  // namespace valsalva::ibm
