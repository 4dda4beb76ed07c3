// One run of the time-order study (validation/time_order): the 3D Taylor-Green vortex
// (initial.type = taylor_green_3d, L = 1, nu = 1/1600) on a periodic n^3 box of side 2 pi,
// driven through the product's run loop (flow::RunLoop) with a fixed time step, and the L2
// difference of two such runs' final velocities.
#pragma once

#include <string>

#include "flow/local_mesh.hpp"
#include "flow/time_scheme.hpp"
#include "validation/tgv_les/tgv_les_run.hpp"

namespace valsalva::validation {

// A time integrator of the study: time.scheme and time.project_stages.
struct TimeVariant {
  flow::TimeScheme scheme = flow::TimeScheme::rk4_jameson;
  bool project_stages = false;
  std::string name() const;  // "rk4_jameson", "rk4_classic+project_stages", ...
};

struct TimeOrderRunSpec {
  TimeVariant variant;
  double velocity = 1;  // U0, m/s; nu = 1/1600 m^2/s whatever U0 (Re = 1600 U0)
  double t_end = 2;     // s
  int steps = 20;       // dt = t_end / steps
  double poisson_tolerance = 1e-10;
};

struct TimeOrderRun {
  double dt = 0;
  int steps = 0;
  double cpu_seconds = 0;   // process CPU time of the run loop, summed over ranks
  double wall_seconds = 0;  // max over ranks
  int max_poisson_iterations = 0;
  flow::VectorField velocity;  // at t_end, every local node of box.local
};

// Collective over box.local's communicator.
TimeOrderRun run_time_order(const TimeOrderRunSpec& spec, const TgvBox& box);

// Collective: sqrt(sum_j V_j |a_j - b_j|^2 / sum_j V_j) over owned nodes.
double velocity_l2_difference(const flow::LocalMesh& local, const flow::VectorField& a,
                              const flow::VectorField& b);

}  // namespace valsalva::validation
