// 2D Taylor-Green vortex on a periodic slab [0, 2 pi]^2 x [0, nz h] (Taylor & Green, Proc. R.
// Soc. A 158, 1937): u = sin x cos y F, v = -cos x sin y F, p = rho/4 (cos 2x + cos 2y) F^2,
// F = exp(-2 nu t), U = L = 1, nu = 1/Re. One run of the projection + RK4 solver to t_end
// from the exact initial state, with velocity and pressure errors against the exact solution,
// and the truncation error of each term of the momentum equation on the exact fields (to see
// which term limits the order). reynolds = inf gives the inviscid (steady Euler) vortex.
// Shared by the validation cases (taylor_green, tgv_inviscid) and the CTest tests.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "flow/pressure_poisson.hpp"

namespace valsalva::validation {

struct TgvSpec {
  std::string cell_type = "hexa";  // mesh::BoxSpec cell types
  double perturbation = 0.0;       // fraction of h
  int n = 16;                      // cells per 2 pi
  int nz = 3;                      // cells across the slab
  double reynolds = 100;
  double t_end = 1.0;
  double cfl = 0.5;   // dt = t_end / ceil(t_end / (cfl h / U))
  double dt_max = 0;  // > 0: dt is also at most this (a time error below the spatial one)
  std::string scheme = "central2";      // flow::make_convection_scheme
  bool stiffness_viscous = false;       // flow::ProjectionOptions::stiffness_viscous
  bool fourth_order_operators = false;  // flow::ProjectionOptions::fourth_order_operators
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
  // Mean kinetic energy sum V |u|^2 / 2 / sum V after every step (index 0: initial state).
  std::vector<double> kinetic_energy;
};

// Through the product's path: validation/taylor_green/taylor_green.toml with the spec as scene
// overrides, run by run::Simulation in `run_dir` (empty: a scratch folder, removed after).
TgvResult run_taylor_green(const TgvSpec& spec, MPI_Comm comm,
                           const std::filesystem::path& run_dir = {});

// The 4th-order set-up at Re 100: central4 with flow::ProjectionOptions::fourth_order_operators
// and dt = c (16 / n)^2 (at most CFL 0.1), c = 0.0125 on hexahedra, 0.05 on tetrahedra (whose
// spatial error is ~100x larger). Why dt ~ h^2: projection + RK4 has an O(dt^2) velocity error
// at Re 100 (measured on hexahedra, n 32: ~0.012 dt^2 in L2, 4.4e-6 of the 5.1e-6 at CFL 0.1
// against a spatial error of ~6e-7; it scales with nu: 1.0e-7 inviscid), so a fixed CFL shows
// order 2 in h; with dt ~ h^2 the time error stays below ~1/5 (hexahedra) and ~1/30
// (tetrahedra) of the 4th-order spatial error at every level (checked by halving dt in
// validation/taylor_green).
TgvSpec fourth_order_spec(const std::string& cell_type, double perturbation, int n);

// Volume-weighted L2 norms over owned nodes of (discrete - exact) for each term of the
// momentum equation evaluated on the exact TGV fields at t = 0: convection div(u u) with
// spec.scheme, viscous nu lap u, pressure gradient grad p / rho, and the divergence of u (exact:
// 0); with the operators of spec.fourth_order_operators.
struct TgvTermErrors {
  double convection = 0, viscous = 0, pressure_gradient = 0, divergence = 0;
};
TgvTermErrors taylor_green_term_errors(const TgvSpec& spec, MPI_Comm comm);

}  // namespace valsalva::validation
