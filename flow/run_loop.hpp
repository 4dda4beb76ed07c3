// A flow run from an initial state to an end time: time step fixed or from CFL and Fourier
// targets (refused beyond the RK4 stability limit, see run_diagnostics.hpp), a progress line
// and a CSV row (log.csv) every log_every steps, fields at the output interval, and a guard
// that stops the run on NaN/Inf or a runaway velocity after writing the last good state.
// Fields go through a FieldSink so that flow/ stays independent of io/ (app/ plugs in
// io::FieldOutput). Every non-periodic boundary patch needs a condition (RunOptions::boundary,
// flow/boundary_conditions.hpp); the log gains the flux through each such patch and the global
// mass imbalance (the sum of all boundary fluxes), and for each lumped outlet its pressure
// (pressure_<patch>) and, for an RCR, its distal pressure (distal_pressure_<patch>); the same
// with the flux go into outlets.csv every step (flow/outlet_log.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/body_forcing.hpp"
#include "flow/boundary_conditions.hpp"
#include "flow/flow_rate_control.hpp"
#include "flow/initial_condition.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::flow {

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

// Something that moves with the flow and pushes on it (app/ plugs in the immersed structures of
// ibm/, so that flow/ stays independent of them): its force density at every RK stage, its own
// update once the step is taken (markers to t^{n+1}) and the largest time step its explicit
// coupling admits. All empty = none: nothing is called or allocated.
struct StepCoupling {
  BodyForce body_force;
  std::function<void(const FlowState&)> finish_step;  // collective, after each flow step
  // Collective, s: the bound for the step after `step` steps, at the current state; +inf = none.
  std::function<double(std::int64_t step)> max_dt;
  std::string max_dt_source;  // what sets max_dt, for the message when time.dt exceeds it
};

// The Poisson matrix's edge weights (flow/poisson_weights.hpp): standard = P1 stiffness on
// all-tetrahedral meshes, two-point weights otherwise; prism_slab = slab_stiffness_weights, the
// P1 weights extended to slabs of right prisms (the DFG benchmark's prism meshes).
enum class PoissonWeights { standard, prism_slab };

struct RunOptions {
  ProjectionOptions projection;  // density, kinematic viscosity, Poisson settings
  PoissonWeights poisson_weights = PoissonWeights::standard;
  TimeOptions time;
  OutputOptions output;
  InitialCondition initial;
  std::vector<BoundarySpec> boundary;  // one per non-periodic patch
  ForcingSpec forcing;                 // a prescribed body force, added to the coupling's
  // forcing.type = flow_rate: the flux through the forcing's section (io::SectionFlux).
  FlowRateControl::SectionFlux section_flux;
  StepCoupling coupling;
  double velocity_limit = 50;  // m/s
  // Tests only: let a time step beyond the stability limit through to exercise the guard.
  bool enforce_stability_limit = true;
};

// Writes named nodal fields (local arrays, owned values read) as `basename` at `time`.
struct FieldSet {
  std::vector<std::pair<std::string, const ScalarField*>> scalars;
  std::vector<std::pair<std::string, const VectorField*>> vectors;
  const VectorField* state_velocity = nullptr;  // the written state's velocity (derived fields)
};
using FieldSink = std::function<void(const std::string& basename, double time, const FieldSet&)>;

// Checkpoint/restart hooks (app/ plugs in io::CheckpointWriter and io::StopSignal, so flow/ stays
// independent of io/). Both are called on every rank after every step and must be collective.
struct RunHooks {
  // Right after each step, before the state checks and the other hooks: may change the velocity
  // (e.g. a validation case's rescaling to a target spectrum during a spin-up). The solver's
  // own arrays (pressure increment, face flux, nu_sgs) are left as the step made them.
  // Collective; empty = none.
  std::function<void(FlowState&, std::int64_t step)> modify_velocity;
  // After each step, before the checkpoint hook: measurements (app/ plugs in io::RunAnalysis).
  std::function<void(const FlowState&, std::int64_t step)> after_step;
  // After each step: the state, the step count, the step's dt and why: a regular step (the hook
  // decides, e.g. every N steps), a stop request (the hook must write) or the run's last step
  // (time.end or time.max_steps reached: the hook writes when periodic checkpoints are on, so a
  // finished run can be extended with --restart latest and a later time.end).
  enum class Moment { regular, stopping, finished };
  std::function<void(const FlowState&, std::int64_t step, double dt, Moment)> checkpoint;
  // True on every rank when the run should stop now (e.g. SIGTERM on any rank).
  std::function<bool()> stop_requested;
};

// A time step the scheme cannot take, a blown-up state or a failed Poisson solve.
// `key` names the scene key at fault, when there is one, so that the front end can point at
// its file and line.
class RunError : public std::runtime_error {
 public:
  explicit RunError(const std::string& what, std::string key = {})
      : std::runtime_error(what), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

struct TaylorGreenError {
  double velocity_l2 = 0;    // sqrt(sum V |u - u_exact|^2 / sum V), m/s
  double velocity_linf = 0;  // m/s
  double exact_l2 = 0;       // sqrt(sum V |u_exact|^2 / sum V), m/s
};

struct RunSummary {
  std::int64_t steps = 0;
  double time = 0;
  double wall_seconds = 0;
  double max_divergence = 0;         // over all steps, 1/s
  double max_divergence_number = 0;  // StepReport::divergence_number, max over all steps
  Eigen::Vector3d max_divergence_position = Eigen::Vector3d::Zero();  // m: where it was
  double max_divergence_time = 0;                                     // s: when
  // StepReport::free_divergence_number (without wall and inflow nodes), max over all steps.
  double max_free_divergence_number = 0;
  Eigen::Vector3d max_free_divergence_position = Eigen::Vector3d::Zero();
  double max_free_divergence_time = 0;
  int max_poisson_iterations = 0;
  std::int64_t total_poisson_iterations = 0;  // summed over the steps of this run
  double max_mass_imbalance = 0;  // max over steps of |sum of all boundary fluxes|, m^3/s
  std::optional<TaylorGreenError> taylor_green;
  bool stopped = false;    // ended early on a stop request (after the checkpoint hook)
  bool steady = false;     // ended on time.steady_tolerance
  double change_rate = 0;  // with steady_tolerance: max |u^{n+1} - u^n| / dt of the last step
};

class RunLoop {
 public:
  // The meshes must outlive the loop.
  RunLoop(const Mesh& mesh, const DualMetrics& metrics, const LocalMesh& local, RunOptions options,
          FieldSink sink = {});

  void set_hooks(RunHooks hooks) { hooks_ = std::move(hooks); }
  // Continue from a checkpointed state (velocity and pressure of every local node, time) after
  // `step` steps instead of the initial condition; log.csv is appended to when it exists.
  // `pressure_increment` (all local nodes; empty = zero) restores the Poisson warm start,
  // `subgrid_viscosity` (all local nodes; empty = zero) the previous step's nu_sgs of an LES,
  // which bounds the first time step (choose_dt), `face_flux` (all local edges; empty = the face
  // value of the velocity) the projected face flux of the state (bitwise restarts).
  // Before run(): start from this velocity (all local nodes) instead of the initial condition's,
  // with the boundary values imposed on it as on the initial condition's (e.g. the steady field
  // of a coarser level, interpolated).
  void set_initial_velocity(VectorField velocity);
  // `lumped_outlets` (LumpedOutlets::saved(); empty = none) the lumped outlets' states.
  void resume(FlowState state, std::int64_t step, const ScalarField& pressure_increment = {},
              const ScalarField& subgrid_viscosity = {}, const EdgeField& face_flux = {},
              const std::vector<double>& lumped_outlets = {});
  // The last pressure increment and nu_sgs (for checkpoints; nu_sgs is empty without a model).
  const ScalarField& pressure_increment() const { return solver_.pressure_increment(); }
  const ScalarField& subgrid_viscosity() const { return solver_.subgrid_viscosity(); }
  const EdgeField& face_flux() const { return solver_.face_flux(); }

  // Runs from the initial condition (or the resumed state) to time.end (or max_steps), or until
  // hooks.stop_requested(). Throws RunError.
  RunSummary run();

  const FlowState& state() const { return state_; }
  // The prescribed body-force density ([forcing], RunOptions::forcing) at every local node, at
  // the time of the state (a time-dependent or controlled force is updated after every step);
  // null without one. For the wall shear stress, whose wall nodes carry a share of it.
  const VectorField* prescribed_force() const { return prescribed_force_.get(); }
  // The flow-rate controller's state (forcing.type = flow_rate; empty otherwise), for
  // checkpoints, and its restoration on a restart (before run()).
  std::vector<double> forcing_state() const;
  void restore_forcing_state(const std::vector<double>& saved);
  // The solver, read-only: its weights for wall forces (flow/wall_force.hpp).
  const ProjectionRK4& solver() const { return solver_; }
  // The boundary conditions, or null when every patch is periodic.
  const BoundaryConditions* boundary() const { return boundary_.get(); }
  // Velocity error against the exact Taylor-Green solution at the current time (collective); a
  // Newtonian fluid's (run() reports none for a non-Newtonian one).
  TaylorGreenError taylor_green_error() const;

 private:
  double choose_dt(double remaining);
  void write_fields(const std::string& basename, const FlowState& state);
  void print_progress(const StepReport& report, double dt, double energy, double per_step,
                      double eta, const std::string& flux_text) const;
  [[noreturn]] void fail(const std::string& why);
  void impose_initial_boundary_values();
  std::vector<double> chosen_poisson_weights(const Mesh& mesh, const DualMetrics& metrics,
                                             const LocalMesh& local) const;
  ProjectionOptions& attach_boundary();

  const LocalMesh& local_;
  RunOptions options_;
  FieldSink sink_;
  std::shared_ptr<BoundaryConditions> boundary_;
  ProjectionRK4 solver_;
  FlowState state_, last_good_;
  std::int64_t step_ = 0;
  bool resumed_ = false;
  RunHooks hooks_;
  TensorField grad_;
  VectorField omega_;
  std::shared_ptr<VectorField> prescribed_force_;       // shared with the solver's body force
  std::shared_ptr<FlowRateControl> flow_rate_control_;  // forcing.type = flow_rate
  void install_forcing();
  void update_forcing_field();
  // log.csv: force_x,force_y,force_z (N/m^3) of a uniform or controlled force and the
  // controller's flow_rate_target (m^3/s); empty for other forcings.
  std::string forcing_log_header() const;
  std::string forcing_log_row() const;
  ScalarField q_;
  std::vector<double> scratch_, fluxes_;
  StabilityRates rates_;
};

}  // namespace valsalva::flow
