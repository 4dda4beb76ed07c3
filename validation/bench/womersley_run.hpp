// One inlet-driven Womersley pipe run for bench_womersley_study's set-up choices and
// test_rank_agreement, through the product's one run path: the scene of the validation case
// validation/womersley (womersley.toml: the extruded disk, mesh/extruded_pipe_generator.hpp;
// womersley_delaunay.toml: Gmsh's 3D Delaunay tetrahedra, mesh/pipe_generator.hpp) with the
// set-up as `--set`-style overrides, run by run::Simulation (validation::run_scene_file). A rigid
// straight pipe with a Womersley-profile sine inflow Q(t) = Q0 (1 + sin(2 pi t / T)), no-slip
// wall and an outlet, started from the exact solution (flow/womersley.hpp; velocity and the
// linear pressure of G(0)) so that the viscous transient of a start from rest, R^2 / (14.7 nu) =
// 3.1 s at Wo = 17, does not hide the discretisation error. Fluid and period of the reference
// experiment (rho 1100, mu 3.6e-3, T = 1 s); R = Wo sqrt(nu T / (2 pi)), mean velocity
// U0 = 5 D / T, so every Wo takes the same number of steps per period at the same nodes per
// diameter. The fixed step (time.dt) is a whole number of steps per phase.
// Sampled by the run's observer: at `phases` equally spaced times of the period
// `sample_period` (0-based), the nodes of the cross-section slab |z - L/2| <= h/2 against
// u_exact(r, t) e_z; with an LES model nu_sgs / nu of each step's last RK stage.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "flow/womersley.hpp"
#include "validation/womersley/womersley_scene.hpp"

namespace valsalva::validation {

// The scene's choices (WomersleyLevel: mesh type and size, outlet, les model, solver options;
// dt is set from cfl) and the sampling.
struct WomersleySetup : WomersleyLevel {
  double cfl = 0.4;  // dt ~ cfl h / u_peak, a whole number of steps per phase
  int phases = 8;
  bool sample_whole_pipe = false;  // sample every node, not only the mid-length slab
};

struct PhaseSample {
  double time = 0;
  double max_error = 0;   // max |u_z - u_exact| / u_peak over the slab
  double l2_error = 0;    // volume-weighted RMS of u_z - u_exact over the slab / u_peak
  double transverse = 0;  // max |u_x, u_y| / u_peak over the slab
  // Mean flux over the middle third, sum V_j u_z / (sum V_j / pi R^2), of the run and of the
  // exact nodal values, and the imposed Q(t), m^3/s.
  double mean_flux = 0, exact_mean_flux = 0, flow_rate = 0;
  std::vector<double> x, y, z, r, u, exact, ux, uy;  // slab nodes (owned, gathered on rank 0)
};

struct WomersleyResult {
  flow::Womersley exact;  // the exact solution of the run
  double radius = 0, length = 0, h = 0, u_peak = 0, dt = 0, wall = 0;
  long nodes = 0;
  std::int64_t steps = 0;
  std::vector<PhaseSample> phases;
  double max_error = 0, l2_error = 0, transverse = 0;  // worst over the phases
  // LES: nu_sgs / nu of each step's last RK stage over owned nodes (max, mean per node-step,
  // max over the middle third |z - L/2| <= L/6).
  double max_nu_ratio = 0, mean_nu_ratio = 0, interior_nu_ratio = 0;
  // Final velocity (3 per node) and pressure by dual node (global order, on every rank).
  std::vector<double> final_velocity, final_pressure;
  double max_divergence = 0;
};

// The scene's overrides of a set-up, with its time.dt.
std::vector<std::string> womersley_setup_overrides(const WomersleySetup& setup);

// Collective over `comm`.
WomersleyResult run_womersley(const WomersleySetup& setup, MPI_Comm comm);

// The fixed time step of a Womersley run: u_peak = max centreline velocity over the period
// (1000 samples), dt ~ cfl h / u_peak rounded down to a whole number of steps per phase.
struct PhaseSteps {
  double u_peak = 0, dt = 0;
  int per_phase = 0;
};
PhaseSteps phase_steps(const flow::Womersley& exact, double period, int phases, double cfl,
                       double h);

}  // namespace valsalva::validation
