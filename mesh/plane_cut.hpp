// The cells of a mesh that a plane cuts, limited to a window: the support of interpolation on
// the plane (statistics sections for PIV planes, analysis/phase_statistics.hpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// Cells the plane through `point` with normal `normal` crosses (nodes on both sides or on it)
// whose bounding box overlaps the axis-aligned box [lo, hi], in increasing order.
std::vector<GlobalIndex> cells_cut_by_plane(const Mesh& mesh, const Eigen::Vector3d& point,
                                            const Eigen::Vector3d& normal,
                                            const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

}  // namespace valsalva::mesh
