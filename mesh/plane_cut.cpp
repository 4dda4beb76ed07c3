#include "mesh/plane_cut.hpp"

#include <algorithm>
#include <cmath>

namespace valsalva::mesh {

std::vector<GlobalIndex> cells_cut_by_plane(const Mesh& mesh, const Eigen::Vector3d& point,
                                            const Eigen::Vector3d& normal,
                                            const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d n = normal.normalized();
  std::vector<GlobalIndex> cells;
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    double below = INFINITY, above = -INFINITY;
    Eigen::Vector3d box_lo = Eigen::Vector3d::Constant(INFINITY), box_hi = -box_lo;
    for (const GlobalIndex node : mesh.cell(c)) {
      const Eigen::Vector3d& x = mesh.nodes[static_cast<std::size_t>(node)];
      const double d = (x - point).dot(n);
      below = std::min(below, d), above = std::max(above, d);
      box_lo = box_lo.cwiseMin(x), box_hi = box_hi.cwiseMax(x);
    }
    if (below <= 0 && above >= 0 && (box_lo.array() <= hi.array()).all() &&
        (box_hi.array() >= lo.array()).all())
      cells.push_back(c);
  }
  return cells;
}

}  // namespace valsalva::mesh
