// 2D Taylor-Green vortex on a periodic slab [0, 2 pi]^2 x [0, nz h] (Taylor & Green, Proc. R.
// Soc. A 158, 1937): u = sin x cos y F, v = -cos x sin y F, p = rho/4 (cos 2x + cos 2y) F^2,
// F = exp(-2 nu t), U = L = 1, nu = 1/Re. One run of the projection + RK4 solver to t_end
// from the exact initial state, with velocity and pressure errors against the exact solution.
// Shared by the validation case and the CTest convergence test.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>

#include "flow/pressure_poisson.hpp"

namespace valsalva::validation {

struct TgvSpec {
  std::string cell_type = "hexa";  // io::BoxSpec cell types
  double perturbation = 0.0;       // fraction of h
  int n = 16;                      // cells per 2 pi
  int nz = 3;                      // cells across the slab
  double reynolds = 100;
  double t_end = 1.0;
  double cfl = 0.5;  // dt = t_end / ceil(t_end / (cfl h / U))
  flow::PoissonOptions poisson;
};

struct TgvResult {
  int n = 0;
  double h = 0;
  std::int64_t nodes = 0;
  int steps = 0;
  double dt = 0;
  double velocity_l2 = 0;    // sqrt(sum V |u - u_exact|^2 / sum V)
  double velocity_linf = 0;  // max |u - u_exact|
  double pressure_l2 = 0;    // zero-mean pressures
  double max_divergence = 0;
  int max_poisson_iterations = 0;
  double wall_seconds = 0;
};

TgvResult run_taylor_green(const TgvSpec& spec, MPI_Comm comm);

}  // namespace valsalva::validation
