// Node-centred median-dual metrics of an unstructured mesh. The dual volume of node j is built
// from sub-tetrahedra (x_j, edge midpoint, face centroid, cell centroid), so every dual volume is
// closed by construction: sum_k S_jk + sum_patches A_j = 0 to round-off.
// Periodic nodes are merged first: metrics are indexed by "dual nodes", one per set of
// periodically identified mesh nodes (see mesh/periodic.hpp).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// Symmetric 3x3 stored as xx, yy, zz, xy, xz, yz.
using SymTensor = std::array<double, 6>;

struct BoundaryDualFace {
  GlobalIndex node = 0;           // dual node
  int patch = 0;                  // index into Mesh::patch_names
  Eigen::Vector3d area{0, 0, 0};  // outward area vector of the node's share of the patch
};

struct DualMetrics {
  // Node identification: dual node of every mesh node, and one representative mesh node per
  // dual node (its position is the dual node's position).
  std::vector<GlobalIndex> dual_of_mesh_node;
  std::vector<GlobalIndex> mesh_node_of_dual;
  std::vector<Eigen::Vector3d> position;

  std::vector<double> volume;                     // dual volume
  std::vector<std::array<GlobalIndex, 2>> edges;  // unique dual-node pairs (j < k)
  std::vector<Eigen::Vector3d> edge_normal;       // S_jk: dual-face area vector oriented j -> k
  std::vector<Eigen::Vector3d> edge_vector;       // x_k - x_j, periodic shift included
  std::vector<BoundaryDualFace> boundary;         // one per (node, patch); none on periodic patches
  std::vector<Eigen::Vector3d> first_moment;      // int_{V_j} (x - x_j) dV
  std::vector<SymTensor> second_moment;           // int_{V_j} (x - x_j)(x - x_j)^T dV
  std::vector<double> h;                          // mesh size: cube root of the dual volume
  // M_j^-1 with M_j = (1 / 2V_j) sum_k S_jk (x_k - x_j)^T: multiplying the edge-based
  // Green-Gauss gradient by it makes the gradient exact for linear fields at every node
  // (M_j = I already at interior nodes of simplicial and uniform meshes; not at boundaries).
  std::vector<Eigen::Matrix3d> gradient_correction;

  GlobalIndex num_nodes() const { return static_cast<GlobalIndex>(volume.size()); }
};

// Throws std::runtime_error naming the mesh, cell and problem when the mesh is unusable
// (untagged boundary face, non-manifold face, unmatched periodic node).
DualMetrics compute_dual_metrics(const Mesh& mesh);

// Volume of the mesh as the sum of cell volumes (face-centroid decomposition), independent of
// the dual construction: the reference for dual-volume sums.
double mesh_volume(const Mesh& mesh);

}  // namespace valsalva::mesh
