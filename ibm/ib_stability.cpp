// Power iteration for the coupling's time-step bound; see ib_stability.hpp.
#include "ibm/ib_stability.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace valsalva::ibm {

StiffnessEigenvalue kernel_mapped_stiffness_eigenvalue(
    DiracTransfer& transfer,
    const std::function<void(const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&)>& apply_stiffness,
    int max_iterations, double tolerance) {
  const int n = transfer.num_markers();
  StiffnessEigenvalue result;
  if (n == 0) return result;
  // Deterministic start with components in every direction (identical on all ranks).
  Eigen::Matrix3Xd v(3, n), kv(3, n), av(3, n);
  for (int a = 0; a < n; ++a)
    v.col(a) =
        Eigen::Vector3d(std::sin(1.3 * a + 0.4), std::cos(0.7 * a + 1.1), std::sin(2.9 * a + 2.3));
  v /= v.norm();
  const int nodes = transfer.mesh().num_local();
  std::vector<Eigen::Vector3d> density(nodes);
  double previous = 0;
  for (int it = 1; it <= max_iterations; ++it) {
    apply_stiffness(v, kv);
    transfer.spread(
        std::span<const Eigen::Vector3d>(reinterpret_cast<const Eigen::Vector3d*>(kv.data()), n),
        density);
    transfer.interpolate(
        std::span<Eigen::Vector3d>(density),
        std::span<Eigen::Vector3d>(reinterpret_cast<Eigen::Vector3d*>(av.data()), n));
    const double norm = av.norm();
    result.iterations = it;
    if (!(norm > 0) || !std::isfinite(norm)) {
      result.lambda = norm;
      return result;
    }
    result.lambda = v.cwiseProduct(av).sum();  // Rayleigh-type estimate, |v| = 1
    result.change = std::abs(result.lambda - previous) / std::abs(result.lambda);
    v = av / norm;
    if (result.change < tolerance) break;
    previous = result.lambda;
  }
  return result;
}

double coupling_time_step_bound(double lambda, double fluid_density, bool per_stage) {
  if (!(lambda > 0)) return std::numeric_limits<double>::infinity();
  const double omega = std::sqrt(lambda / fluid_density);
  return (per_stage ? 2 * std::sqrt(2.0) : 2.0) / omega;
}

}  // namespace valsalva::ibm
