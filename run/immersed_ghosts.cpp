#include "run/immersed_ghosts.hpp"

#include <algorithm>
#include <cmath>

#include "ibm/kernels.hpp"

namespace valsalva::run {

mesh::GhostRegion marker_ghost_region(const scene::ImmersedSetup& setup,
                                      const mesh::DualMetrics& metrics, double distance) {
  mesh::GhostRegion region;
  if (setup.empty()) return region;
  Eigen::AlignedBox3d markers;
  for (const auto& s : setup.structures) {
    const Eigen::Matrix3Xd& x = s.initial.cols() > 0 ? s.initial : s.mesh.X;
    for (Eigen::Index k = 0; k < x.cols(); ++k) markers.extend(Eigen::Vector3d(x.col(k)));
  }
  const double margin = 0.25 * markers.sizes().maxCoeff();
  Eigen::AlignedBox3d near(markers.min().array() - margin, markers.max().array() + margin);
  double h = 0;
  for (std::size_t d = 0; d < metrics.position.size(); ++d)
    if (near.contains(metrics.position[d])) h = std::max(h, metrics.h[d]);
  const auto& transfer = setup.options.transfer;
  const double r = ibm::support_radius(transfer.kernel, std::max(h, transfer.min_h));
  region.distance = distance > 0 ? distance : std::sqrt(3.0) * r + h;
  region.box = Eigen::AlignedBox3d(near.min().array() - region.distance,
                                   near.max().array() + region.distance);
  return region;
}

}  // namespace valsalva::run
