// Periodic node identification by translation: every node of a slave patch is matched to the
// node of its master patch at x - translation (within a tolerance relative to the mesh size).
// Matched nodes become one unknown; chains (edges and corners of a box periodic in several
// directions) resolve to a single representative.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

struct PeriodicMap {
  // For every mesh node: the representative mesh node, and the shift with
  // x_node = x_representative + shift.
  std::vector<GlobalIndex> representative;
  std::vector<Eigen::Vector3d> shift;
  bool any = false;
};

// Throws MeshTopologyError naming the unmatched node, its position and the patches.
PeriodicMap match_periodic_nodes(const Mesh& mesh, double relative_tolerance = 1e-8);

}  // namespace valsalva::mesh
