// Pressure(-increment) Poisson equation  lap(x) = f  with the compact edge Laplacian
//   (1/V_j) sum_k a_jk (x_k - x_j),  a_jk = |S_jk|^2 / (S_jk . d_jk)
// (the two-point part of flow::laplacian; the non-orthogonal correction is left out of the
// matrix so that it stays a symmetric M-matrix with a compact stencil that AMG handles well and
// has no checkerboard null space, unlike div(grad)). Assembled once as a hypre IJ/ParCSR matrix
// in the LocalMesh's contiguous global numbering and solved by PCG preconditioned by BoomerAMG
// (Falgout & Yang, "hypre: a library of high performance preconditioners", ICCS 2002;
// Henson & Yang, "BoomerAMG", Appl. Numer. Math. 41, 2002). The AMG hierarchy is set up once in
// the constructor and reused by every solve; the solve starts from the x it is given (warm
// start).
// Boundary patches are homogeneous Neumann (walls, inlets, convective outlets) unless their nodes
// are flagged Dirichlet (pressure outlets, PoissonOptions::dirichlet): a Dirichlet row is
// d_j x_j = d_j g_j (d_j the row's diagonal, to keep AMG's scaling) with g the value x holds on
// entry, and its column is eliminated into the right-hand side of the other rows, so the matrix
// stays symmetric positive definite. Without Dirichlet nodes (periodic, or every boundary a
// velocity condition) the operator is singular with the constants as null space: the
// right-hand side is made consistent by removing its mean, and the solution is returned with
// zero volume-weighted mean.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

struct PoissonOptions {
  double tolerance = 1e-8;  // relative residual ||b - A x||_2 / ||b||_2
  int max_iterations = 200;
  // BoomerAMG settings (hypre's numbering): HMIS coarsening, extended+i interpolation,
  // hybrid symmetric Gauss-Seidel smoothing; strength threshold 0.25 rather than hypre's 3D
  // advice 0.5: on the hexahedral box and the valve root's tetrahedra it coarsens faster (lower
  // operator complexity) at no more iterations (validation/notes/flow_throughput.md).
  double strong_threshold = 0.25;
  int coarsen_type = 10;
  int interp_type = 6;
  int relax_type = 6;
  int aggressive_levels = 0;
  int print_level = 0;
  // Per local node (owned and ghosts): 1 = Dirichlet node, its value is the x given to solve();
  // empty = none (flow::BoundaryConditions::pressure_dirichlet() fills it).
  std::vector<char> dirichlet;
};

struct PoissonResult {
  int iterations = 0;
  double relative_residual = 0;
  bool converged = false;
};

class PressurePoisson {
 public:
  // `weights` are flow::laplacian_weights(mesh); the mesh must outlive the solver.
  PressurePoisson(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                  PoissonOptions options = {});
  ~PressurePoisson();
  PressurePoisson(const PressurePoisson&) = delete;
  PressurePoisson& operator=(const PressurePoisson&) = delete;

  // Solves lap(x) = f (f per unit volume, owned values used); x is the initial guess on entry
  // and the solution (owned and ghosts) on return. Throws when the iteration cap is reached
  // without meeting the tolerance, naming the residual.
  PoissonResult solve(const std::vector<double>& f, std::vector<double>& x);

  const PoissonOptions& options() const { return options_; }
  // True when no node is Dirichlet: constants are the null space (mean removed).
  bool singular() const { return singular_; }

 private:
  struct Hypre;
  const mesh::LocalMesh& mesh_;
  PoissonOptions options_;
  bool singular_ = true;
  std::unique_ptr<Hypre> hypre_;
};

}  // namespace valsalva::flow
