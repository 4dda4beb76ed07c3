// Point location in the replicated hybrid mesh: the containing cell of a point and the
// isoparametric weights of its nodes, so that a nodal field interpolates as sum_k w_k f(node_k).
// Tetrahedra: barycentric coordinates; hexahedra: trilinear; prisms: linear triangle x linear
// segment; pyramids: the rational (Bedrosian) shape functions, which reproduce linear fields
// (G. Bedrosian, "Shape functions and integration formulas for three-dimensional finite element
// analysis", IJNME 35, 1992). Non-affine cells are inverted by Newton's method on the reference
// coordinates (Zienkiewicz & Taylor, The Finite Element Method, vol. 1, ch. 9).
// Candidate cells come from the tree's spatial index (core::BucketGrid) over the centres of the
// cells' bounding boxes: cells are grouped by size (powers of two of their largest half-extent)
// and each group's grid is queried with a box of that group's largest half-extent, so a graded
// mesh costs O(groups) buckets per point, not the small cells under the largest one. Candidates
// are tried in ascending id: a point on a face shared by two cells goes to the lower cell id, the
// same on every rank.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "core/bucket_grid.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::mesh {

struct PointLocation {
  mesh::GlobalIndex cell = -1;
  int count = 0;                             // nodes of the cell
  std::array<mesh::GlobalIndex, 8> nodes{};  // mesh node ids
  std::array<double, 8> weights{};           // sum to 1
  Eigen::Vector3d reference{0, 0, 0};        // reference coordinates in the cell

  // Interpolates a nodal field given as value_of_node(mesh node). Nodes with a negligible
  // weight (|w| <= 1e-14) are skipped, so a point on a face or a node does not read the
  // off-face nodes (which may be NaN, e.g. outside a statistics subset).
  template <class Get>
  double interpolate(Get&& value_of_node) const {
    double s = 0;
    for (int k = 0; k < count; ++k)
      if (std::abs(weights[k]) > 1e-14) s += weights[k] * value_of_node(nodes[k]);
    return s;
  }
};

// Shape functions of `type` at reference point `xi` (Gmsh node order) and their derivatives
// d N_k / d xi_j in row k; returns the node count.
int shape_functions(mesh::CellType type, const Eigen::Vector3d& xi, std::array<double, 8>& n,
                    std::array<Eigen::Vector3d, 8>& dn);

class PointLocator {
 public:
  explicit PointLocator(const mesh::Mesh& mesh);
  // The grids view their groups' centres: moving keeps them valid, copying would not.
  PointLocator(const PointLocator&) = delete;
  PointLocator& operator=(const PointLocator&) = delete;
  PointLocator(PointLocator&&) = default;
  PointLocator& operator=(PointLocator&&) = default;

  // The containing cell (lowest id if several), or nullopt when the point is outside the mesh.
  // `tolerance` is relative to the cell's reference size (points that far outside still count).
  std::optional<PointLocation> locate(const Eigen::Vector3d& x, double tolerance = 1e-9) const;

  const mesh::Mesh& mesh() const { return *mesh_; }

 private:
  std::optional<PointLocation> try_cell(mesh::GlobalIndex c, const Eigen::Vector3d& x,
                                        double tolerance) const;
  // Cells whose largest bounding-box half-extent lies in [2^e, 2^(e+1)), for one e.
  struct SizeGroup {
    double reach = 0;                      // largest half-extent of the group
    std::vector<Eigen::Vector3d> centres;  // bounding-box centres
    std::vector<mesh::GlobalIndex> cells;  // ascending ids
    core::BucketGrid grid;                 // over `centres`
  };
  const mesh::Mesh* mesh_;
  Eigen::Vector3d lo_, hi_;
  std::vector<SizeGroup> groups_;
};

}  // namespace valsalva::mesh
