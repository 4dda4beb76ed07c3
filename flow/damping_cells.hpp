// The pressure damping term of flow::ProjectionRK4 split into the shares of the tetrahedra, so
// that it can be left out where an immersed structure holds a pressure jump.
//
// The damping flux of edge e = (j, k) is dt/rho [S_e . (g_j + g_k)/2 - w_e (p_k - p_j)] with S_e
// the median-dual face and w_e the P1 stiffness weight of the Poisson matrix (g = grad p^n). Both
// are sums over the tetrahedra that hold the edge: S_e = sum_T S_e^T (the two triangles (edge
// midpoint, face centroid, cell centroid) of each face of T on the edge) and w_e = sum_T w_e^T
// (-V_T grad N_j . grad N_k). Leaving out whole tetrahedra keeps the damping's Laplacian a sum
// of the positive semi-definite element matrices, between 0 and the Poisson matrix, so the
// pressure modes it damps decay at any mix; leaving out edges does not, because a quarter of the
// P1 weights of a Gmsh mesh are negative (a valve run with an edge mask diverged in 92 steps).
// Each tetrahedron's share is exact for linear pressure (sum_k S_jk^T = -V_T grad N_j), so the
// remaining term still vanishes for linear pressure.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "flow/face_flux.hpp"
#include "flow/operators.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::flow {

class DampingCells {
 public:
  // The tetrahedra of `mesh` whose four nodes are local (all those that hold an edge of an
  // owned node). Throws std::invalid_argument when the mesh has other cells (their Poisson
  // weights are not a sum of element matrices).
  DampingCells(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
               const mesh::LocalMesh& local);

  // flux_e -= c_T [S_e^T . (g_j + g_k)/2 - w_e^T (p_k - p_j)] for every tetrahedron T with a
  // node marked in `nodes` (one value per local node) and each of its six edges e: c_T = c
  // where T has no node on the boundary, c_boundary where it has. The boundary's tetrahedra need
  // some of their damping: the odd-even pressure mode that walls and inlets excite grew without
  // any where a leaflet's kernel reached the wall of a sinus (a valve run diverged at
  // t = 0.12 s, docs/valve.md).
  void remove(const std::vector<char>& nodes, double c, double c_boundary,
              const VectorField& grad_p, const ScalarField& p, EdgeField& flux) const;

  // Sums of the weight shares w_e^T (1 - c_T) over the local tetrahedra, with c_T of remove()
  // for c = 1 (empty `nodes`: c_T = 0 everywhere), per local edge: with all, the Poisson weights
  // and the dual faces on every edge of an owned node (for tests).
  std::vector<double> weight_sums(const std::vector<char>& nodes = {}, double c_boundary = 0) const;
  std::vector<Eigen::Vector3d> face_sums() const;

 private:
  struct Tetra {
    std::array<int, 4> node;  // local nodes
    std::array<int, 6> edge;  // local edges, in the order of edge_pairs
    std::array<double, 6> weight;
    std::array<Eigen::Vector3d, 6> face;  // oriented along the local edge (j -> k)
    bool boundary = false;                // a node on the boundary
  };
  std::vector<Tetra> tetras_;
  std::size_t num_edges_ = 0;
};

}  // namespace valsalva::flow
