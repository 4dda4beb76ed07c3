// What a flow run is asked to do, as the scene states it (scene/scene_keys_flow.cpp fills it;
// run/run_loop.hpp runs it): the time-step policy, the outputs and progress, the initial and
// boundary conditions, the prescribed forcing and the coupling to immersed structures.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "flow/body_forcing.hpp"
#include "flow/boundary_conditions.hpp"
#include "flow/flow_rate_control.hpp"
#include "flow/initial_condition.hpp"
#include "flow/projection_rk4.hpp"

namespace valsalva::scene {

struct TimeOptions {
  double end = 0;        // s
  double dt = 0;         // s; 0 = from the cfl and fourier targets
  double cfl = 0.5;      // target max |u| dt / h
  double fourier = 0.2;  // target max nu dt / h^2
  // > 0 (with dt = 0): dt = this fraction of the RK4 stability limit of convection and
  // viscosity together (flow/run_diagnostics.hpp) instead of the cfl and fourier targets.
  double stability_fraction = 0;
  std::int64_t max_steps = 0;  // 0 = no cap
  // Shorten steps to land on every field output time; false = full steps only (fields at the
  // first step at or after each output time), so that output does not change the results.
  bool land_on_output = true;
  // Times (s, ascending) the run lands on exactly, by shortening the step before each as for
  // the end (e.g. the measuring stations of a validation case); empty = none.
  std::vector<double> land_on;
  // > 0: stop once max over nodes and components of |u^{n+1} - u^n| / dt is below this (m/s^2):
  // a steady state; RunSummary::steady says whether it was reached before end or max_steps.
  double steady_tolerance = 0;
};

// How progress reaches the terminal (rank 0's stdout): `lines`, one line per log_every steps
// (for log files and pipes); `status`, one line rewritten in place (for a terminal) with the
// cycle and phase when cycle_period > 0, the ETA and the throughput; `quiet`, nothing but the
// start and end lines. log.csv gets its rows in every mode.
enum class Progress { lines, status, quiet };

struct OutputOptions {
  std::filesystem::path dir;  // run directory: log.csv and the Taylor-Green error go there
  double interval = 0;        // 0 = no field output
  bool interval_in_steps = false;
  bool velocity = true, pressure = true, vorticity = true, q_criterion = false;
  int log_every = 10;
  bool print = true;  // anything on stdout (rank 0); false = tests
  Progress progress = Progress::lines;
  double cycle_period = 0;  // s; > 0 shows cycle and phase in the status line
};

// Something that moves with the flow and pushes on it (run::Simulation plugs in the immersed
// structures of ibm/): its force density at every RK stage, its own
// update once the step is taken (markers to t^{n+1}) and the largest time step its explicit
// coupling admits. All empty = none: nothing is called or allocated.
struct StepCoupling {
  flow::BodyForce body_force;
  std::function<void(const flow::FlowState&)> finish_step;  // collective, after each flow step
  // Collective, s: the bound for the step after `step` steps, at the current state; +inf = none.
  std::function<double(std::int64_t step)> max_dt;
  std::string max_dt_source;  // what sets max_dt, for the message when time.dt exceeds it
  // Collective: the local nodes the flow step adds no pressure damping on, at the current
  // state (flow::ProjectionRK4::set_undamped_nodes); empty function = damping everywhere.
  std::function<void(std::vector<char>&)> undamped_nodes;
  double kept_damping = 0.0;              // the fraction of the damping kept there
  double kept_damping_at_boundary = 1.0;  // ... in its cells (edges) with a boundary node
};

// The Poisson matrix's edge weights (flow/poisson_weights.hpp): standard = P1 stiffness on
// all-tetrahedral meshes, two-point weights otherwise; prism_slab = slab_stiffness_weights, the
// P1 weights extended to slabs of right prisms (the DFG benchmark's prism meshes).
enum class PoissonWeights { standard, prism_slab };

struct RunOptions {
  flow::ProjectionOptions projection;  // density, kinematic viscosity, Poisson settings
  PoissonWeights poisson_weights = PoissonWeights::standard;
  TimeOptions time;
  OutputOptions output;
  flow::InitialCondition initial;
  std::vector<flow::BoundarySpec> boundary;  // one per non-periodic patch
  flow::ForcingSpec forcing;                 // a prescribed body force, added to the coupling's
  // forcing.type = flow_rate: the flux through the forcing's section (analysis::SectionFlux).
  flow::FlowRateControl::SectionFlux section_flux;
  StepCoupling coupling;
  double velocity_limit = 50;  // m/s
  // Tests only: let a time step beyond the stability limit through to exercise the guard.
  bool enforce_stability_limit = true;
};

}  // namespace valsalva::scene
