// Validity checks of a mesh::Mesh, and the cell geometry they rest on.
//
// Cell volumes use the decomposition the median-dual metrics use: every cell is split into
// sub-tetrahedra (x_a, edge midpoint, face centroid, cell centroid), two per face edge, so a
// cell whose sub-tetrahedra are all positive has positive dual-volume contributions at every
// node (Barth, "Aspects of unstructured grids and finite-volume solvers for the Euler and
// Navier-Stokes equations", VKI LS 1994-05, sec. 3: median-dual control volumes).
#pragma once

#include <Eigen/Core>
#include <span>
#include <stdexcept>
#include <string>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// A mesh that is not usable: the message names mesh.source, the cell/face/node and the problem.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws MeshError on the first problem found, checked in this order:
// array sizes, node index out of range, degenerate cell (|V| < 1e-12 h^3, h = longest edge),
// inverted cell (a negative sub-tetrahedron), unused node, cell face shared by more than two
// cells, tagged boundary face that is not a cell face / lies inside / is tagged twice,
// boundary cell face not covered by any patch (missing physical group).
void check_mesh(const Mesh& mesh);

// Signed volume of cell c by the sub-tetrahedron decomposition (exact for planar faces).
double cell_volume(const Mesh& mesh, GlobalIndex c);

// Smallest signed sub-tetrahedron volume of cell c (negative: inverted somewhere).
double min_subtet_volume(const Mesh& mesh, GlobalIndex c);

// Area vector of a polygonal face (right-hand rule over its node order), by triangles around
// the face centroid.
Eigen::Vector3d face_area(const Mesh& mesh, std::span<const GlobalIndex> face_nodes);

// Longest edge of cell c (edges taken from its faces).
double longest_edge(const Mesh& mesh, GlobalIndex c);

}  // namespace valsalva::mesh
