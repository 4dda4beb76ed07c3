// One run of the time-order study (validation/time_order): the scene time_order.toml (the 3D
// Taylor-Green vortex, initial.type = taylor_green_3d, on a periodic n^3 box of side 2 pi) with
// the run's cells, end time, fixed time step and time integrator as overrides, run as users run
// it (run::Simulation and its run loop), and the L2 difference of two runs' final velocities.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <string>
#include <vector>

#include "flow/operators.hpp"
#include "flow/time_scheme.hpp"

namespace valsalva::validation {

// A time integrator of the study: time.scheme and time.project_stages.
struct TimeVariant {
  flow::TimeScheme scheme = flow::TimeScheme::rk4_jameson;
  bool project_stages = false;
  std::string name() const;  // "rk4_jameson", "rk4_classic+project_stages", ...
};

struct TimeOrderRunSpec {
  TimeVariant variant;
  int cells = 16;       // per side
  double velocity = 1;  // U0, m/s; nu = 1/1600 m^2/s whatever U0 (Re = 1600 U0)
  double t_end = 1;     // s
  int steps = 5;        // time.dt = t_end / steps
};

struct TimeOrderRun {
  double dt = 0;
  int steps = 0;
  double cpu_seconds = 0;   // process CPU time of Simulation::run, summed over ranks
  double wall_seconds = 0;  // max over ranks
  int max_poisson_iterations = 0;
  flow::VectorField velocity;  // at t_end, owned nodes in local order
  std::vector<double> volume;  // their dual volumes
  // Owned nodes' positions: every run of one mesh partitions it the same way; checked.
  std::vector<Eigen::Vector3d> position;
};

// Collective over `comm`; the run directory is `run_dir` (replaced).
TimeOrderRun run_time_order(const TimeOrderRunSpec& spec, const std::filesystem::path& run_dir,
                            MPI_Comm comm);

// Collective: sqrt(sum_j V_j |a_j - b_j|^2 / sum_j V_j) over the owned nodes of two runs of the
// same mesh (b = nullptr: the L2 norm of a); throws when their nodes differ.
double velocity_l2_difference(const TimeOrderRun& a, const TimeOrderRun* b, MPI_Comm comm);

}  // namespace valsalva::validation
