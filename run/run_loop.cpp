// The time loop of a flow run; see run_loop.hpp.
#include "run/run_loop.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <utility>

#include "flow/poisson_weights.hpp"
#include "flow/womersley.hpp"
#include "run/outlet_log.hpp"

namespace valsalva::run {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

std::vector<double> RunLoop::chosen_poisson_weights(const mesh::Mesh& mesh,
                                                    const mesh::DualMetrics& metrics,
                                                    const mesh::LocalMesh& local) const {
  if (options_.poisson_weights == scene::PoissonWeights::standard)
    return flow::poisson_weights(mesh, metrics, local);
  try {
    return flow::slab_stiffness_weights(mesh, metrics, local);
  } catch (const std::invalid_argument& e) {
    throw RunError(std::string("poisson.weights = prism_slab: ") + e.what(), "poisson.weights");
  }
}

void RunLoop::install_damping_cells(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics) {
  // The coupling (or poisson.damping = increment) leaves the damping of p^n out in some cells:
  // by whole tetrahedra where the Poisson weights are P1 (some negative), by edges where they
  // are two-point weights (non-negative); the slab weights may be negative and have no element
  // split here (the scene reader refuses them with the increment form).
  if (options_.poisson_weights == scene::PoissonWeights::prism_slab)
    throw RunError(
        "poisson.weights = prism_slab with immersed structures: the pressure damping cannot be "
        "left out near the markers on slab weights; set immersed.pressure_damping_in_support = "
        "1 or use the standard weights",
        "poisson.weights");
  const bool tetrahedra = std::all_of(mesh.cell_types.begin(), mesh.cell_types.end(),
                                      [](auto t) { return t == mesh::CellType::tetra; });
  if (tetrahedra)
    solver_.set_damping_cells(std::make_shared<flow::DampingCells>(mesh, metrics, local_));
}

RunLoop::RunLoop(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                 const mesh::LocalMesh& local, scene::RunOptions options, io::FieldSink sink)
    : local_(local),
      options_(std::move(options)),
      sink_(std::move(sink)),
      solver_(local, attach_boundary(), chosen_poisson_weights(mesh, metrics, local)) {
  if (options_.coupling.undamped_nodes || options_.projection.damp_pressure_increment)
    install_damping_cells(mesh, metrics);
  const auto& ic = options_.initial;
  const int n = local.num_local();
  state_.velocity.assign(n, Eigen::Vector3d::Zero());
  state_.pressure.assign(n, 0.0);
  if (ic.type == flow::InitialType::taylor_green) {
    const flow::TaylorGreen tg{ic.velocity, ic.length, options_.projection.viscosity,
                               options_.projection.density};
    for (int j = 0; j < n; ++j) {
      state_.velocity[j] = tg.velocity(local.position[j], 0.0);
      state_.pressure[j] = tg.pressure(local.position[j], 0.0);
    }
  } else if (ic.type == flow::InitialType::taylor_green_3d) {
    const flow::TaylorGreen3d tg{ic.velocity, ic.length, options_.projection.density};
    for (int j = 0; j < n; ++j) {
      state_.velocity[j] = tg.velocity(local.position[j]);
      state_.pressure[j] = tg.pressure(local.position[j]);
    }
  } else if (ic.type == flow::InitialType::cyclic_sines) {
    for (int j = 0; j < n; ++j)
      state_.velocity[j] = flow::cyclic_sines(local.position[j], ic.velocity, ic.length);
  } else if (ic.type == flow::InitialType::womersley) {
    const auto exact = flow::Womersley::from_sine(ic.radius, options_.projection.viscosity,
                                                  ic.flow_rate, ic.amplitude, ic.period, ic.phase);
    const Eigen::Vector3d axis = ic.axis.normalized();
    const double g0 = exact.pressure_gradient(0.0);
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d x = local.position[j] - ic.point;
      const double s = x.dot(axis), r = std::min((x - s * axis).norm(), ic.radius);
      state_.velocity[j] = exact.velocity(r, 0.0) * axis;
      if (ic.pressure_gradient) state_.pressure[j] = -options_.projection.density * g0 * s;
    }
  } else if (ic.type == flow::InitialType::plane_poiseuille) {
    for (int j = 0; j < n; ++j) state_.velocity[j] = flow::plane_poiseuille(local.position[j], ic);
  }  // InitialType::rest: at rest, p = 0
  impose_initial_boundary_values();
  install_forcing();
}

void RunLoop::impose_initial_boundary_values() {
  if (boundary_) {
    boundary_->impose_pressure(state_.pressure);
    boundary_->hold_outlets(state_.velocity);
    boundary_->impose(state_.velocity, state_.time);
    if (auto* lumped = solver_.lumped_outlets())
      lumped->start(state_.velocity, state_.pressure, state_.time);
  }
  last_good_ = state_;
}

void RunLoop::set_initial_velocity(flow::VectorField velocity) {
  if (velocity.size() != static_cast<std::size_t>(local_.num_local()))
    throw RunError(fmt::format("flow run: initial velocity of {} nodes, the local mesh has {}",
                               velocity.size(), local_.num_local()));
  state_.velocity = std::move(velocity);
  impose_initial_boundary_values();
}

void RunLoop::resume(flow::FlowState state, std::int64_t step,
                     const flow::ScalarField& pressure_increment,
                     const flow::ScalarField& subgrid_viscosity, const flow::EdgeField& face_flux,
                     const std::vector<double>& lumped_outlets) {
  const auto n = static_cast<std::size_t>(local_.num_local());
  if (state.velocity.size() != n || state.pressure.size() != n)
    throw RunError(
        fmt::format("flow run: resumed state has {} velocity and {} pressure values, "
                    "the local mesh {} nodes",
                    state.velocity.size(), state.pressure.size(), n));
  state_ = std::move(state);
  last_good_ = state_;
  step_ = step;
  if (!pressure_increment.empty()) solver_.set_pressure_increment(pressure_increment);
  if (!subgrid_viscosity.empty()) solver_.set_subgrid_viscosity(subgrid_viscosity);
  if (!face_flux.empty()) solver_.set_face_flux(face_flux, state_.velocity);
  if (auto* lumped = solver_.lumped_outlets()) {
    if (lumped_outlets.empty())
      throw RunError("flow run: the checkpoint has no lumped-outlet states for the scene's " +
                     std::to_string(lumped->count()) + " resistance/RCR outlets");
    lumped->restore(lumped_outlets);
  }
  update_forcing_field();  // a time-dependent force at the resumed time
  resumed_ = true;
}

// Boundary conditions when the mesh has non-periodic patches (or the options name some).
flow::ProjectionOptions& RunLoop::attach_boundary() {
  auto& p = options_.projection;
  const auto faces = static_cast<std::int64_t>(local_.boundary.size());
  if (local_.comm.sum(faces) == 0 && options_.boundary.empty()) return p;
  try {
    boundary_ = std::make_shared<flow::BoundaryConditions>(local_, options_.boundary, p.viscosity);
  } catch (const std::invalid_argument& e) {
    throw RunError(std::string("flow run: ") + e.what(), "boundary");
  }
  p.boundary = boundary_;
  p.poisson.dirichlet =
      boundary_->has_pressure_outlet() ? boundary_->pressure_dirichlet() : std::vector<char>{};
  return p;
}

double RunLoop::choose_dt(double remaining) {
  const auto& t = options_.time;
  // A non-Newtonian fluid: its nodal viscosity of the current velocity (+ nu_sgs), or the cap of
  // a law that has one at every node (flow/viscosity_model.hpp, viscosity_cap). LES: each node's
  // nu + nu_sgs of the previous step's last stage bounds its own viscous rate (Gershgorin on the
  // edge viscosity of flow/viscous_stress.hpp), not the largest nu_sgs anywhere: that one lies in
  // the coarse cells of a jet, and paired with the smallest cells (a valve frame's edges) it cut
  // the time step of a valve run several times below what any node needs.
  const auto& rheology = options_.projection.rheology;
  const auto& nu_sgs = solver_.subgrid_viscosity();
  const auto with_subgrid = [&](double nu) -> const flow::ScalarField& {
    viscosity_bound_.resize(nu_sgs.size());
    for (std::size_t i = 0; i < nu_sgs.size(); ++i) viscosity_bound_[i] = nu + nu_sgs[i];
    return viscosity_bound_;
  };
  const auto& weights = solver_.laplacian_weights();
  const double cap = flow::viscosity_cap(rheology);
  if (cap <= 0 && solver_.variable_viscosity()) {
    rates_ = flow::stability_rates(local_, weights, solver_.viscosity_field(state_.velocity),
                                   state_.velocity, scratch_);
  } else {
    const double nu = cap > 0 ? cap / options_.projection.density : options_.projection.viscosity;
    rates_ = nu_sgs.empty() ? flow::stability_rates(local_, weights, nu, state_.velocity, scratch_)
                            : flow::stability_rates(local_, weights, with_subgrid(nu),
                                                    state_.velocity, scratch_);
  }
  // The immersed coupling's own bound (+inf without one). It caps the step before the check
  // against the flow's stability limit: targets whose step the coupling cuts anyway are not
  // refused (a valve run in diastole: CFL 0.5 and Fourier 0.2 together just above the limit,
  // the coupling's bound 14 times below it).
  double coupling_bound = std::numeric_limits<double>::infinity();
  if (const auto& c = options_.coupling; c.max_dt) {
    coupling_bound = c.max_dt(step_);
    if (t.dt > 0 && options_.enforce_stability_limit && t.dt > coupling_bound)
      throw RunError(fmt::format("time.dt = {:.6g} s exceeds the largest time step {:.6g} s that "
                                 "{} admits at step {}: set time.dt <= {:.6g}, or time.dt = 0 "
                                 "to let the run keep below it",
                                 t.dt, coupling_bound, c.max_dt_source, step_, coupling_bound),
                     "time.dt");
  }
  const double limit = 1.0 / rates_.stability;  // +inf at rest without viscosity
  double dt = t.dt;
  if (dt > 0) {
    if (options_.enforce_stability_limit && dt > limit)
      throw RunError(
          fmt::format(
              "time.dt = {:.6g} s exceeds the stability limit {:.6g} s of the explicit RK4 terms "
              "at "
              "step {} (CFL {:.3g}, Fourier number {:.3g}; convection and viscosity by Gershgorin "
              "bounds, see flow/run_diagnostics.hpp): set time.dt <= {:.6g} or time.dt = 0 to "
              "derive "
              "it from time.cfl",
              dt, limit, step_, dt * rates_.convective, dt * rates_.viscous, limit),
          "time.dt");
  } else {
    dt = std::numeric_limits<double>::infinity();
    if (t.stability_fraction > 0) {
      dt = t.stability_fraction * limit;
    } else {
      if (rates_.convective > 0) dt = t.cfl / rates_.convective;
      if (rates_.viscous > 0) dt = std::min(dt, t.fourier / rates_.viscous);
    }
    if (!std::isfinite(dt))
      throw RunError(
          "time.dt = 0 asks for a time step from time.cfl and time.fourier, but the "
          "fluid is at rest and inviscid: set time.dt",
          "time.dt");
    dt = std::min(dt, coupling_bound);
    if (options_.enforce_stability_limit && dt > limit * (1 + 1e-12))
      throw RunError(
          fmt::format(
              "time.cfl = {:.4g} and time.fourier = {:.4g} give dt = {:.6g} s, beyond the "
              "stability "
              "limit {:.6g} s of the explicit RK4 terms at step {} (the limit corresponds to CFL "
              "{:.3g}, Fourier number {:.3g}; see flow/run_diagnostics.hpp): lower time.cfl or "
              "time.fourier",
              t.cfl, t.fourier, dt, limit, step_, limit * rates_.convective,
              limit * rates_.viscous),
          "time.cfl");
  }
  // Land on the next event (end, output time) without a sliver of a step: the last two steps
  // before it share the remaining time when it is less than two steps.
  if (remaining <= dt * (1 + 1e-9)) return remaining;
  return remaining < 2 * dt ? remaining / 2 : dt;
}

void RunLoop::write_fields(const std::string& basename, const flow::FlowState& state) {
  if (!sink_) return;
  const auto& out = options_.output;
  io::FieldSet set;
  set.state_velocity = &state.velocity;
  if (out.velocity) set.vectors.emplace_back("velocity", &state.velocity);
  if (out.pressure) set.scalars.emplace_back("pressure", &state.pressure);
  if (out.vorticity) {
    flow::gradient(local_, state.velocity, grad_);
    flow::vorticity(grad_, omega_);
    set.vectors.emplace_back("vorticity", &omega_);
  }
  if (out.q_criterion) {
    if (!out.vorticity) flow::gradient(local_, state.velocity, grad_);
    flow::q_criterion(grad_, q_);
    set.scalars.emplace_back("q_criterion", &q_);
  }
  sink_(basename, state.time, set);
}

void RunLoop::print_progress(const flow::StepReport& report, double dt, double energy,
                             double per_step, double eta, const std::string& flux_text) const {
  const auto& out = options_.output;
  const double cfl = dt * rates_.convective, fourier = dt * rates_.viscous;
  // Node-steps per second over all ranks: the throughput a user compares between runs.
  const double rate = per_step > 0 ? double(local_.global_nodes) / per_step : 0.0;
  if (out.progress == scene::Progress::lines) {
    fmt::print(
        "step {:>7} t {:.6e} s dt {:.3e} s CFL {:.3f} Fo {:.3f} max|div| {:.2e} 1/s "
        "KE {:.6e} J Poisson {} it {:.1e}{} wall/step {:.3e} s ({:.3g} node-steps/s) ETA {:.1f} "
        "s\n",
        step_, state_.time, dt, cfl, fourier, report.max_divergence, energy,
        report.poisson.iterations, report.poisson.relative_residual, flux_text, per_step, rate,
        eta);
  } else if (out.progress == scene::Progress::status) {
    std::string cycle;
    if (out.cycle_period > 0) {
      const double c = state_.time / out.cycle_period;
      cycle = fmt::format("cycle {} phase {:.3f} ", static_cast<std::int64_t>(std::floor(c)),
                          c - std::floor(c));
    }
    fmt::print(
        "\r\x1b[K{}t {:.6g} s step {} CFL {:.2f} Poisson {} it | {:.3g} node-steps/s | "
        "ETA {:.0f} s",
        cycle, state_.time, step_, cfl, report.poisson.iterations, rate, eta);
    std::fflush(stdout);
  }
}

void RunLoop::fail(const std::string& why) {
  const bool written = static_cast<bool>(sink_);
  write_fields("last_good", last_good_);
  throw RunError(fmt::format(
      "flow run stopped at step {} (t = {:.9g} s): {}; {}; to go on with a smaller step from a "
      "checkpoint written before the trouble: valsalva run SCENE --restart "
      "RUN_DIR/checkpoints/checkpoint_<step>.h5 --set time.cfl=<smaller>",
      step_, state_.time, why,
      written ? fmt::format("the last good state (t = {:.9g} s) is in last_good.xmf of the run "
                            "directory",
                            last_good_.time)
              : std::string("no field output was configured")));
}

RunSummary RunLoop::run() {
  const auto& t = options_.time;
  const auto& out = options_.output;
  const bool root = local_.comm.root();
  const double rho = options_.projection.density;
  const auto start = Clock::now();
  std::ofstream csv;
  bool header = true;
  if (root && !out.dir.empty()) {
    // A resumed run continues an existing log (rows after the checkpoint's step may repeat when
    // the earlier run went on past its last checkpoint).
    std::error_code ec;
    const bool append = resumed_ && std::filesystem::file_size(out.dir / "log.csv", ec) > 0 && !ec;
    csv.open(out.dir / "log.csv", append ? std::ios::app : std::ios::trunc);
    if (!csv) throw RunError("flow run: cannot write " + (out.dir / "log.csv").string());
    header = !append;
  }
  if (csv.is_open() && header) {
    csv << "step,time,dt,cfl,fourier,max_div,kinetic_energy,poisson_iterations,"
           "poisson_residual,wall_per_step,eta";
    if (boundary_)
      for (int p : boundary_->spec_patches()) csv << ",flux_" << local_.patch_names[p];
    csv << ",mass_imbalance,div_h_over_u,div_h_over_u_free";
    if (const auto* lumped = solver_.lumped_outlets())
      for (int k = 0; k < lumped->count(); ++k) {
        const auto& name = local_.patch_names[lumped->patch(k)];
        csv << ",pressure_" << name;
        if (const char* column = distal_column(lumped->spec(k).type)) csv << "," << column << name;
      }
    csv << forcing_log_header();
    csv << "\n";
  }
  std::optional<OutletLog> outlet_log;
  if (const auto* lumped = solver_.lumped_outlets()) {
    outlet_log.emplace(out.dir, *lumped, local_.patch_names, root, resumed_);
    if (!resumed_) outlet_log->write(step_, state_.time);
  }
  const bool fields = out.interval > 0;
  if (fields) write_fields("fields", state_);
  const double eps = 1e-12 * std::max(t.end, std::numeric_limits<double>::min());
  double next_output = out.interval;  // in seconds when !interval_in_steps
  // Resumed: the same sequence of output times as an uninterrupted run (same additions).
  if (fields && !out.interval_in_steps)
    while (next_output <= state_.time + eps) next_output += out.interval;
  std::int64_t last_written = step_, last_logged = step_;
  auto last_log_time = Clock::now();
  RunSummary summary;
  flow::StepReport report;
  double dt = 0;
  const double energy0 = flow::kinetic_energy(local_, rho, state_.velocity);  // collective
  if (root && out.print)
    fmt::print("flow: t = {:.9g} s (step {}), kinetic energy {:.6e} J, running to t = {:.6g} s\n",
               state_.time, step_, energy0, t.end);

  while (t.end - state_.time > eps && (t.max_steps == 0 || step_ < t.max_steps) &&
         !summary.steady) {
    double remaining = t.end - state_.time;
    if (fields && !out.interval_in_steps && t.land_on_output)
      remaining = std::min(remaining, next_output - state_.time);
    for (double stop : t.land_on)  // the first one ahead
      if (stop - state_.time > eps) {
        remaining = std::min(remaining, stop - state_.time);
        break;
      }
    dt = choose_dt(remaining);
    last_good_.velocity = state_.velocity;  // sizes match: no allocation
    last_good_.pressure = state_.pressure;
    last_good_.time = state_.time;
    try {
      if (options_.coupling.undamped_nodes) {
        options_.coupling.undamped_nodes(undamped_);
        solver_.set_undamped_nodes(undamped_, options_.coupling.kept_damping,
                                   options_.coupling.kept_damping_at_boundary);
      }
      report = solver_.step(state_, dt);
      if (flow_rate_control_) {
        // The flux through the section held at its target (flow/flow_rate_control.hpp).
        flow::EdgeField flux = solver_.face_flux();
        flow_rate_control_->correct(state_.velocity, flux, dt, rho, state_.time);
        solver_.set_face_flux(flux, state_.velocity);
      }
      update_forcing_field();
      if (options_.coupling.finish_step) options_.coupling.finish_step(state_);
    } catch (const std::exception& e) {
      ++step_;
      const auto bad =
          flow::find_bad_state(local_, state_.velocity, state_.pressure, options_.velocity_limit);
      fail(bad.empty() ? std::string(e.what()) : bad + " (" + e.what() + ")");
    }
    ++step_;
    if (hooks_.modify_velocity) hooks_.modify_velocity(state_, step_);
    if (auto bad =
            flow::find_bad_state(local_, state_.velocity, state_.pressure, options_.velocity_limit);
        !bad.empty())
      fail(bad);
    summary.max_divergence = std::max(summary.max_divergence, report.max_divergence);
    if (report.divergence_number > summary.max_divergence_number) {
      summary.max_divergence_number = report.divergence_number;
      summary.max_divergence_position = report.divergence_position;
      summary.max_divergence_time = state_.time;
    }
    if (report.free_divergence_number > summary.max_free_divergence_number) {
      summary.max_free_divergence_number = report.free_divergence_number;
      summary.max_free_divergence_position = report.free_divergence_position;
      summary.max_free_divergence_time = state_.time;
    }
    summary.max_poisson_iterations =
        std::max(summary.max_poisson_iterations, report.poisson.iterations);
    summary.total_poisson_iterations += report.poisson.iterations;
    // Boundary fluxes (outward, m^3/s) and their sum, the global mass imbalance.
    double imbalance = 0;
    if (boundary_) {
      fluxes_ = boundary_->patch_fluxes(state_.velocity);
      for (double f : fluxes_) imbalance += f;
      summary.max_mass_imbalance = std::max(summary.max_mass_imbalance, std::abs(imbalance));
    }

    if (outlet_log) outlet_log->write(step_, state_.time);
    if (t.steady_tolerance > 0) {
      double change = 0;
      for (int j = 0; j < local_.num_owned; ++j)
        change =
            std::max(change, (state_.velocity[j] - last_good_.velocity[j]).cwiseAbs().maxCoeff());
      summary.change_rate = local_.comm.max(change) / dt;
      summary.steady = summary.change_rate < t.steady_tolerance;
    }
    const bool finished = t.end - state_.time <= eps || step_ == t.max_steps || summary.steady;
    if (step_ % out.log_every == 0 || finished) {
      const auto now = Clock::now();
      const double per_step =
          local_.comm.max(seconds(last_log_time, now)) / static_cast<double>(step_ - last_logged);
      last_log_time = now;
      last_logged = step_;
      const double eta = per_step * std::max(0.0, t.end - state_.time) / dt;
      const double energy = flow::kinetic_energy(local_, rho, state_.velocity);
      const double cfl = dt * rates_.convective, fourier = dt * rates_.viscous;
      std::string flux_text, flux_csv;
      if (boundary_) {
        for (int p : boundary_->spec_patches()) {
          flux_text += fmt::format(" {} {:.3e}", local_.patch_names[p], fluxes_[p]);
          flux_csv += fmt::format(",{:.9e}", fluxes_[p]);
        }
        flux_text = " flux" + flux_text + fmt::format(" imbalance {:.1e} m3/s", imbalance);
      }
      std::string lumped_csv;
      if (const auto* lumped = solver_.lumped_outlets())
        for (int k = 0; k < lumped->count(); ++k) {
          const auto& s = lumped->state(k);
          flux_text +=
              fmt::format(" p_{} {:.6g} Pa", local_.patch_names[lumped->patch(k)], s.pressure);
          lumped_csv += fmt::format(",{:.17g}", s.pressure);
          if (distal_column(lumped->spec(k).type)) lumped_csv += fmt::format(",{:.17g}", s.distal);
        }
      if (root && out.print) print_progress(report, dt, energy, per_step, eta, flux_text);
      if (csv.is_open())
        csv << fmt::format(
                   "{},{:.17g},{:.17g},{:.9g},{:.9g},{:.9g},{:.17g},{},{:.6g},{:.6g},{:.6g}{},{:."
                   "6e},{:.6e},{:.6e}{}\n",
                   step_, state_.time, dt, cfl, fourier, report.max_divergence, energy,
                   report.poisson.iterations, report.poisson.relative_residual, per_step, eta,
                   flux_csv, imbalance, report.divergence_number, report.free_divergence_number,
                   lumped_csv + forcing_log_row())
            << std::flush;
    }
    if (fields) {
      const bool due = out.interval_in_steps
                           ? step_ % static_cast<std::int64_t>(std::llround(out.interval)) == 0
                           : state_.time >= next_output - eps;
      if (due) {
        write_fields("fields", state_);
        last_written = step_;
        if (!out.interval_in_steps)
          while (next_output <= state_.time + eps) next_output += out.interval;
      }
    }
    if (hooks_.after_step) hooks_.after_step(state_, step_);
    const bool stopping = hooks_.stop_requested && hooks_.stop_requested();
    if (hooks_.checkpoint)
      hooks_.checkpoint(state_, step_, dt,
                        stopping   ? RunHooks::Moment::stopping
                        : finished ? RunHooks::Moment::finished
                                   : RunHooks::Moment::regular);
    if (stopping) {
      summary.stopped = true;
      break;
    }
  }
  if (fields && last_written != step_ && !summary.stopped) write_fields("fields", state_);
  if (root && out.print && out.progress == scene::Progress::status) fmt::print("\n");

  summary.steps = step_;
  summary.time = state_.time;
  summary.wall_seconds = local_.comm.max(seconds(start, Clock::now()));
  // The decaying vortex exp(-2 nu t / L^2) is the exact solution of a Newtonian fluid only: a
  // non-Newtonian one's viscosity varies in space and time, so no error is reported against it.
  const bool newtonian = options_.projection.rheology.law == flow::ViscosityLaw::newtonian;
  if (options_.initial.type == flow::InitialType::taylor_green && !summary.stopped && !newtonian &&
      root && out.print)
    fmt::print(
        "Taylor-Green velocity error: not reported, the decaying vortex is the exact solution of "
        "a Newtonian fluid only (flow.viscosity_model = {})\n",
        flow::viscosity_law_name(options_.projection.rheology.law));
  if (options_.initial.type == flow::InitialType::taylor_green && !summary.stopped && newtonian) {
    const auto e = taylor_green_error();
    summary.taylor_green = e;
    if (root && !out.dir.empty()) {
      std::ofstream f(out.dir / "taylor_green_error.csv");
      f << "time,velocity_l2,velocity_linf,exact_l2,relative_l2\n"
        << fmt::format("{:.17g},{:.9e},{:.9e},{:.9e},{:.9e}\n", state_.time, e.velocity_l2,
                       e.velocity_linf, e.exact_l2, e.velocity_l2 / e.exact_l2);
    }
    if (root && out.print)
      fmt::print(
          "Taylor-Green velocity error at t = {:.6g} s: L2 {:.6e} m/s ({:.4e} of the exact "
          "L2 norm), Linf {:.6e} m/s\n",
          state_.time, e.velocity_l2, e.velocity_l2 / e.exact_l2, e.velocity_linf);
  }
  return summary;
}

TaylorGreenError RunLoop::taylor_green_error() const {
  const flow::TaylorGreen tg{options_.initial.velocity, options_.initial.length,
                             options_.projection.viscosity, options_.projection.density};
  double volume = 0, e2 = 0, einf = 0, x2 = 0;
  for (int j = 0; j < local_.num_owned; ++j) {
    const auto exact = tg.velocity(local_.position[j], state_.time);
    const double du = (state_.velocity[j] - exact).norm();
    volume += local_.volume[j];
    e2 += local_.volume[j] * du * du;
    x2 += local_.volume[j] * exact.squaredNorm();
    einf = std::max(einf, du);
  }
  const auto& c = local_.comm;
  volume = c.sum(volume);
  return {std::sqrt(c.sum(e2) / volume), c.max(einf), std::sqrt(c.sum(x2) / volume)};
}

}  // namespace valsalva::run
