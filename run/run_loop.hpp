// A flow run from an initial state to an end time: time step fixed or from CFL and Fourier
// targets (refused beyond the RK4 stability limit, see flow/run_diagnostics.hpp), a progress line
// and a CSV row (log.csv) every log_every steps, fields at the output interval, and a guard
// that stops the run on NaN/Inf or a runaway velocity after writing the last good state.
// Fields go through a FieldSink (run::Simulation plugs in io::FieldOutput). What to run comes as
// scene::RunOptions (scene/run_options.hpp). Every non-periodic boundary patch needs a condition
// (RunOptions::boundary, flow/boundary_conditions.hpp); the log gains the flux through each such
// patch and the global mass imbalance (the sum of all boundary fluxes), and for each lumped outlet
// its pressure (pressure_<patch>) and, for an RCR, its distal pressure (distal_pressure_<patch>);
// the same with the flux go into outlets.csv every step (run/outlet_log.hpp).
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
#include "io/field_set.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"
#include "scene/run_options.hpp"

namespace valsalva::run {

// Checkpoint/restart hooks (run::Simulation plugs in io::CheckpointWriter and run::StopSignal).
// Both are called on every rank after every step and must be collective.
struct RunHooks {
  // Right after each step, before the state checks and the other hooks: may change the velocity
  // (e.g. a validation case's rescaling to a target spectrum during a spin-up). The solver's
  // own arrays (pressure increment, face flux, nu_sgs) are left as the step made them.
  // Collective; empty = none.
  std::function<void(flow::FlowState&, std::int64_t step)> modify_velocity;
  // After each step, before the checkpoint hook: measurements (run::Simulation plugs in
  // analysis::RunAnalysis).
  std::function<void(const flow::FlowState&, std::int64_t step)> after_step;
  // After each step: the state, the step count, the step's dt and why: a regular step (the hook
  // decides, e.g. every N steps), a stop request (the hook must write) or the run's last step
  // (time.end or time.max_steps reached: the hook writes when periodic checkpoints are on, so a
  // finished run can be extended with --restart latest and a later time.end).
  enum class Moment { regular, stopping, finished };
  std::function<void(const flow::FlowState&, std::int64_t step, double dt, Moment)> checkpoint;
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
  RunLoop(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics, const mesh::LocalMesh& local,
          scene::RunOptions options, io::FieldSink sink = {});

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
  void set_initial_velocity(flow::VectorField velocity);
  // `lumped_outlets` (LumpedOutlets::saved(); empty = none) the lumped outlets' states.
  void resume(flow::FlowState state, std::int64_t step,
              const flow::ScalarField& pressure_increment = {},
              const flow::ScalarField& subgrid_viscosity = {},
              const flow::EdgeField& face_flux = {},
              const std::vector<double>& lumped_outlets = {});
  // The last pressure increment and nu_sgs (for checkpoints; nu_sgs is empty without a model).
  const flow::ScalarField& pressure_increment() const { return solver_.pressure_increment(); }
  const flow::ScalarField& subgrid_viscosity() const { return solver_.subgrid_viscosity(); }
  const flow::EdgeField& face_flux() const { return solver_.face_flux(); }

  // Runs from the initial condition (or the resumed state) to time.end (or max_steps), or until
  // hooks.stop_requested(). Throws RunError.
  RunSummary run();

  const flow::FlowState& state() const { return state_; }
  // The prescribed body-force density ([forcing], RunOptions::forcing) at every local node, at
  // the time of the state (a time-dependent or controlled force is updated after every step);
  // null without one. For the wall shear stress, whose wall nodes carry a share of it.
  const flow::VectorField* prescribed_force() const { return prescribed_force_.get(); }
  // The flow-rate controller's state (forcing.type = flow_rate; empty otherwise), for
  // checkpoints, and its restoration on a restart (before run()).
  std::vector<double> forcing_state() const;
  void restore_forcing_state(const std::vector<double>& saved);
  // The solver, read-only: its weights for wall forces (flow/wall_force.hpp).
  const flow::ProjectionRK4& solver() const { return solver_; }
  // The boundary conditions, or null when every patch is periodic.
  const flow::BoundaryConditions* boundary() const { return boundary_.get(); }
  // Velocity error against the exact Taylor-Green solution at the current time (collective); a
  // Newtonian fluid's (run() reports none for a non-Newtonian one).
  TaylorGreenError taylor_green_error() const;

 private:
  double choose_dt(double remaining);
  void write_fields(const std::string& basename, const flow::FlowState& state);
  void print_progress(const flow::StepReport& report, double dt, double energy, double per_step,
                      double eta, const std::string& flux_text) const;
  [[noreturn]] void fail(const std::string& why);
  void impose_initial_boundary_values();
  std::vector<double> chosen_poisson_weights(const mesh::Mesh& mesh,
                                             const mesh::DualMetrics& metrics,
                                             const mesh::LocalMesh& local) const;
  flow::ProjectionOptions& attach_boundary();

  const mesh::LocalMesh& local_;
  scene::RunOptions options_;
  io::FieldSink sink_;
  std::shared_ptr<flow::BoundaryConditions> boundary_;
  flow::ProjectionRK4 solver_;
  flow::FlowState state_, last_good_;
  std::vector<char> undamped_;  // options_.coupling.undamped_nodes of the current step
  std::int64_t step_ = 0;
  bool resumed_ = false;
  RunHooks hooks_;
  flow::TensorField grad_;
  flow::VectorField omega_;
  std::shared_ptr<flow::VectorField> prescribed_force_;       // shared with the solver's body force
  std::shared_ptr<flow::FlowRateControl> flow_rate_control_;  // forcing.type = flow_rate
  void install_forcing();
  // With a coupling that leaves the pressure damping out near its markers.
  void install_damping_cells(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics);
  void update_forcing_field();
  // log.csv: force_x,force_y,force_z (N/m^3) of a uniform or controlled force and the
  // controller's flow_rate_target (m^3/s); empty for other forcings.
  std::string forcing_log_header() const;
  std::string forcing_log_row() const;
  flow::ScalarField q_;
  std::vector<double> scratch_, fluxes_;
  flow::ScalarField viscosity_bound_;  // nu + nu_sgs per node for the time-step bound
  flow::StabilityRates rates_;
};

}  // namespace valsalva::run
