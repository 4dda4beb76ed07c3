// Projection + low-storage RK4 step; see projection_rk4.hpp.
#include "flow/projection_rk4.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "flow/face_flux.hpp"
#include "flow/viscous_stress.hpp"

namespace valsalva::flow {

ProjectionRK4::ProjectionRK4(const mesh::LocalMesh& mesh, ProjectionOptions options,
                             std::vector<double> poisson_weights)
    : mesh_(mesh),
      options_(options),
      weights_(flow::laplacian_weights(mesh)),
      poisson_weights_(poisson_weights.empty() ? weights_ : std::move(poisson_weights)),
      convection_(make_convection_scheme(options.scheme, mesh)),
      old_convection_(options.scheme == ConvectionKind::central4 &&
                      !options.fourth_order_operators),
      poisson_(mesh, poisson_weights_, options.poisson),
      dp_(mesh.num_local(), 0.0),
      rk_(tableau(options.time_scheme)),
      rheology_(options.rheology.law != ViscosityLaw::newtonian) {
  if (!(options.density > 0) || !(options.viscosity >= 0))
    throw std::invalid_argument("flow::ProjectionRK4: density must be > 0 (got " +
                                std::to_string(options.density) + ") and viscosity >= 0 (got " +
                                std::to_string(options.viscosity) + ")");
  if (const auto problem = viscosity_model_problem(options.rheology))
    throw std::invalid_argument("flow::ProjectionRK4: " + viscosity_law_name(options.rheology.law) +
                                " " + problem->parameter + ": " + problem->message);
  if (options.fourth_order_operators) {
    if (rheology_)
      throw std::invalid_argument(
          "flow::ProjectionRK4: the 4th-order operators have no variable-viscosity "
          "(non-Newtonian) viscous term; run without fourth_order_operators");
    order4_ = std::make_unique<Order4Operators>(mesh, poisson_weights_);
  }
  auto* bc = options_.boundary.get();
  if (bc && std::any_of(bc->specs().begin(), bc->specs().end(),
                        [](const BoundarySpec& s) { return lumped_type(s.type); }))
    lumped_ = std::make_unique<LumpedOutlets>(
        mesh, *bc, [this](const ScalarField& f, ScalarField& x) { poisson_.solve(f, x); },
        [this](const ScalarField& p, VectorField& g) { pressure_gradient(p, g); });
}

void ProjectionRK4::pressure_gradient(const ScalarField& p, VectorField& grad) {
  if (order4_)
    order4_->gradient(p, grad);
  else
    gradient(mesh_, p, grad);
}

void ProjectionRK4::projection_divergence(const VectorField& u, ScalarField& div) {
  if (order4_)
    order4_->divergence(u, div);
  else
    divergence(mesh_, u, div);
}

void ProjectionRK4::momentum_rhs(const VectorField& u, const EdgeField& flux, VectorField& rhs,
                                 int stage) {
  // central4 with the 2nd-order operators (the LES path) keeps the flux form of
  // flow/convection_central4.hpp: with the skew form validate tgv_les --quick (32^3 sigma) moves
  // its -dE/dt peak from t = 7.94 to 6.08 (peak time check -2.89 against 1.5), see issue 21.
  if (old_convection_)
    convection_->apply(u, conv_);
  else
    convection_->apply(u, flux, conv_);
  if (options_.subgrid_viscosity || rheology_) {
    // The gradient's ghosts are valid, so nu_sgs and nu(gamma_dot) are computed on ghosts too:
    // no exchange.
    velocity_gradient(u);
    if (options_.subgrid_viscosity) {
      nu_sgs_.resize(grad_u_.size());
      options_.subgrid_viscosity(stage, grad_u_, nu_sgs_);
    }
    if (order4_) {
      // The molecular term with the 4th-order operator, the subgrid term with the 2nd-order
      // full-stress operator: the model itself is only O(Delta^2) accurate, and the full-stress
      // form keeps its variable-viscosity term dissipative.
      order4_->viscous(options_.viscosity, u, grad_u_, rhs);
      viscous_stress(mesh_, weights_, nu_sgs_, u, grad_u_, subgrid_rhs_);
      for (int i = 0; i < mesh_.num_local(); ++i) rhs[i] += subgrid_rhs_[i];
    } else {
      total_viscosity();
      viscous_stress(mesh_, weights_, nu_eff_, u, grad_u_, rhs);
    }
  } else if (options_.viscosity > 0) {
    velocity_gradient(u);
    if (order4_)
      order4_->viscous(options_.viscosity, u, grad_u_, rhs);
    else
      viscous(mesh_, viscous_weights(), options_.viscosity, u, grad_u_, rhs, viscous_correction());
  } else {
    rhs.assign(mesh_.num_local(), Eigen::Vector3d::Zero());
  }
  for (int i = 0; i < mesh_.num_local(); ++i) rhs[i] -= conv_[i];
  if (options_.boundary) {
    options_.boundary->stabilize_backflow(u, rhs);
    if (rheology_)  // nu_eff_ holds the whole viscosity
      options_.boundary->drop_outlet_viscous_flux(grad_u_, 0.0, nu_eff_, rhs);
    else if (options_.viscosity > 0 || options_.subgrid_viscosity)
      options_.boundary->drop_outlet_viscous_flux(grad_u_, options_.viscosity, nu_sgs_, rhs);
  }
}

void ProjectionRK4::velocity_gradient(const VectorField& u) {
  if (stage_gradient_known_) {
    std::swap(grad_u_, grad_flux_);  // the same gradient(mesh_, u), already computed
    stage_gradient_known_ = false;
    return;
  }
  gradient(mesh_, u, grad_u_);
}

void ProjectionRK4::projection_flux(const VectorField& u, EdgeField& flux) {
  if (order4_) {
    gradient(mesh_, u, grad_flux_);
    hermite_face_flux(mesh_, u, grad_flux_, flux);
  } else {
    central_face_flux(mesh_, u, flux);
  }
}

void ProjectionRK4::scheme_flux(const VectorField& u, EdgeField& flux) {
  if (options_.scheme == ConvectionKind::central4) {
    gradient(mesh_, u, grad_flux_);
    hermite_face_flux(mesh_, u, grad_flux_, flux);
  } else {
    central_face_flux(mesh_, u, flux);
  }
}

void ProjectionRK4::set_face_flux(const EdgeField& flux, const VectorField& velocity) {
  if (flux.size() != mesh_.edges.size() ||
      velocity.size() != static_cast<std::size_t>(mesh_.num_local()))
    throw std::invalid_argument(
        "flow::ProjectionRK4::set_face_flux: " + std::to_string(flux.size()) + " face fluxes and " +
        std::to_string(velocity.size()) + " velocities for " + std::to_string(mesh_.edges.size()) +
        " local edges and " + std::to_string(mesh_.num_local()) + " local nodes");
  flux_ = flux;
  flux_velocity_ = velocity;
}

const EdgeField& ProjectionRK4::convective_flux(const VectorField& u) {
  // F_1 = P_c(v^n) + F^n - P_p(v^n); without a face flux of v^n, P_c(v^n).
  scheme_flux(u, stage_flux_);
  const bool known =
      flux_velocity_.size() == u.size() && std::equal(u.begin(), u.end(), flux_velocity_.begin());
  if (!known) {
    flux_offset_.assign(mesh_.edges.size(), 0.0);
    return stage_flux_;
  }
  projection_flux(u, flux_offset_);
  for (std::size_t e = 0; e < flux_offset_.size(); ++e)
    flux_offset_[e] = flux_[e] - flux_offset_[e];
  for (std::size_t e = 0; e < flux_offset_.size(); ++e) stage_flux_[e] += flux_offset_[e];
  return stage_flux_;
}

void ProjectionRK4::momentum_rhs(const VectorField& u, VectorField& rhs, int stage) {
  momentum_rhs(u, convective_flux(u), rhs, stage);
}

PoissonResult ProjectionRK4::correct(VectorField& u, EdgeField& flux, double dt_over_rho,
                                     ScalarField& dp) {
  face_flux_divergence(mesh_, flux, u, div_);
  for (auto& d : div_) d /= dt_over_rho;
  const PoissonResult result = poisson_.solve(div_, dp);
  add_compact_gradient(mesh_, poisson_weights_, -dt_over_rho, dp, flux);
  pressure_gradient(dp, grad_dp_);  // grad_p_ (grad p^n) is still needed by later stages
  for (int i = 0; i < mesh_.num_local(); ++i) u[i] -= dt_over_rho * grad_dp_[i];
  return result;
}

PoissonResult ProjectionRK4::project(VectorField& u, ScalarField& q) {
  if (u.size() != static_cast<std::size_t>(mesh_.num_local()) || q.size() != u.size())
    throw std::invalid_argument("flow::ProjectionRK4::project: " + std::to_string(u.size()) +
                                " velocities and " + std::to_string(q.size()) +
                                " values of q for " + std::to_string(mesh_.num_local()) +
                                " local nodes");
  projection_flux(u, flux_);
  const PoissonResult result = correct(u, flux_, 1.0, q);
  flux_velocity_ = u;
  return result;
}

void ProjectionRK4::set_pressure_increment(const ScalarField& dp) {
  if (dp.size() != dp_.size())
    throw std::invalid_argument(
        "flow::ProjectionRK4::set_pressure_increment: " + std::to_string(dp.size()) +
        " values for " + std::to_string(dp_.size()) + " local nodes");
  dp_ = dp;
}

void ProjectionRK4::set_undamped_nodes(const std::vector<char>& nodes, double kept,
                                       double kept_at_boundary) {
  for (const double f : {kept, kept_at_boundary})
    if (!(f >= 0 && f <= 1))
      throw std::invalid_argument("flow::ProjectionRK4::set_undamped_nodes: kept fraction " +
                                  std::to_string(f) + " is not in [0, 1]");
  if (!nodes.empty() && nodes.size() != static_cast<std::size_t>(mesh_.num_local()))
    throw std::invalid_argument(
        "flow::ProjectionRK4::set_undamped_nodes: " + std::to_string(nodes.size()) +
        " values for " + std::to_string(mesh_.num_local()) + " local nodes");
  mark_boundary_nodes();
  kept_damping_ = kept;
  kept_damping_at_boundary_ = kept_at_boundary;
  undamped_ = nodes;
}

void ProjectionRK4::set_subgrid_viscosity(const ScalarField& nu_sgs) {
  if (!options_.subgrid_viscosity)
    throw std::invalid_argument(
        "flow::ProjectionRK4::set_subgrid_viscosity: the solver has no subgrid model");
  if (nu_sgs.size() != dp_.size())
    throw std::invalid_argument(
        "flow::ProjectionRK4::set_subgrid_viscosity: " + std::to_string(nu_sgs.size()) +
        " values for " + std::to_string(dp_.size()) + " local nodes");
  nu_sgs_ = nu_sgs;
}

namespace {

// The share of the damping an edge (j, k) keeps on the edge path (no DampingCells): all of it
// away from the support (undamped empty or neither node marked), else the support's fraction,
// its boundary's where a node is on the boundary (as DampingCells' tetrahedra do).
double kept_fraction(const std::vector<char>& undamped, const std::vector<char>& on_boundary,
                     double kept, double kept_at_boundary, int j, int k) {
  if (undamped.empty() || !(undamped[j] || undamped[k])) return 1.0;
  return on_boundary[j] || on_boundary[k] ? kept_at_boundary : kept;
}

}  // namespace

void ProjectionRK4::predicted_flux(const VectorField& w, double dt, const ScalarField& p,
                                   EdgeField& flux) {
  projection_flux(w, flux);
  if ((options_.boundary || options_.periodic_pressure_damping) && options_.pressure_damping) {
    add_damping(dt, grad_p_, p, flux);  // grad_p_ holds grad p^n (step())
    if (options_.damp_pressure_increment) remove_previous_pressure_damping(dt, flux);
  }
}

void ProjectionRK4::add_damping(double dt, const VectorField& grad_p, const ScalarField& p,
                                EdgeField& flux) {
  // Pressure damping (Rhie & Chow, AIAA J. 21, 1983, in its node-centred form): the face flux
  // of v* takes the face-velocity correction dt/rho (avg(grad p^n) - grad p^n|_face), i.e.
  // the divergence gains div(grad p^n) - lap(p^n) with the wide divergence of the wide
  // gradient and the compact, linearly exact Laplacian of flow/operators.hpp (their boundary
  // faces cancel). The odd-even pressure mode that inlets and wall corners excite is invisible
  // to the wide operators and otherwise stays in the steady state; the term vanishes for
  // linear pressure and is O(h^2) for smooth ones. The compact Laplacian here must be the
  // Poisson matrix's own operator (P1 weights on tetrahedra): with the two-point Laplacian
  // instead, the damping pumps energy into the flow on tetrahedral meshes and a DFG cylinder
  // run blew up in 15 steps at any dt.
  const double c = dt / options_.density;
  if (undamped_.empty() || cells_) {
    add_central_flux(mesh_, c, grad_p, flux);
    add_compact_gradient(mesh_, poisson_weights_, -c, p, flux);
    if (!undamped_.empty())
      cells_->remove(undamped_, (1 - kept_damping_) * c, (1 - kept_damping_at_boundary_) * c,
                     grad_p, p, flux);
    return;
  }
  damping_flux_.assign(flux.size(), 0.0);
  add_central_flux(mesh_, c, grad_p, damping_flux_);
  add_compact_gradient(mesh_, poisson_weights_, -c, p, damping_flux_);
  for (std::size_t e = 0; e < flux.size(); ++e) {
    const auto [j, k] = mesh_.edges[e];
    flux[e] +=
        kept_fraction(undamped_, on_boundary_, kept_damping_, kept_damping_at_boundary_, j, k) *
        damping_flux_[e];
  }
}

void ProjectionRK4::remove_previous_pressure_damping(double dt, EdgeField& flux) {
  // What add_damping() added for previous_p_ = p^n - theta dp (step()), with the same kept
  // fractions, is taken back out of the cells (edges) with no node on an open boundary: there
  // the damping acts on theta dp.
  const double c = dt / options_.density;
  const auto& prev = previous_p_;
  const auto& grad_prev = grad_previous_p_;
  mark_boundary_nodes();
  if (cells_) {
    // All cells, less those at an open boundary, less the share the support had already left
    // out. (A support cell at an open boundary would keep 1 - kept of previous_p_'s damping
    // instead of none: the leaflets' kernels do not reach an inlet or an outlet.)
    if (every_node_.empty()) every_node_.assign(static_cast<std::size_t>(mesh_.num_local()), 1);
    cells_->remove(every_node_, c, c, grad_prev, prev, flux);
    cells_->remove(open_boundary_, -c, -c, grad_prev, prev, flux);
    if (!undamped_.empty())
      cells_->remove(undamped_, -(1 - kept_damping_) * c, -(1 - kept_damping_at_boundary_) * c,
                     grad_prev, prev, flux);
    return;
  }
  damping_flux_.assign(flux.size(), 0.0);
  add_central_flux(mesh_, c, grad_prev, damping_flux_);
  add_compact_gradient(mesh_, poisson_weights_, -c, prev, damping_flux_);
  for (std::size_t e = 0; e < flux.size(); ++e) {
    const auto [j, k] = mesh_.edges[e];
    if (open_boundary_[j] || open_boundary_[k]) continue;
    flux[e] -=
        kept_fraction(undamped_, on_boundary_, kept_damping_, kept_damping_at_boundary_, j, k) *
        damping_flux_[e];
  }
}

void ProjectionRK4::mark_boundary_nodes() {
  if (!on_boundary_.empty()) return;
  const auto n = static_cast<std::size_t>(mesh_.num_local());
  on_boundary_.assign(n, 0);
  open_boundary_.assign(n, 0);
  std::vector<char> open_patch(mesh_.patch_names.size(), 1);  // patches with no condition: open
  if (const auto* bc = options_.boundary.get())
    for (std::size_t q = 0; q < open_patch.size(); ++q)
      for (const auto& spec : bc->specs())
        if (spec.patch == mesh_.patch_names[q])
          open_patch[q] = spec.type != BoundaryType::wall && spec.type != BoundaryType::slip;
  for (const auto& f : mesh_.boundary) {
    on_boundary_[f.node] = 1;
    if (open_patch.at(static_cast<std::size_t>(f.patch))) open_boundary_[f.node] = 1;
  }
}

int ProjectionRK4::project_stage(VectorField& w, double c, double dt, double t,
                                 const ScalarField& p) {
  // The incremental projection of step() over c dt: the stage's dp is about c (p^{n+1} - p^n),
  // so c dp of the last step is the warm start (checkpointed with dp: bitwise restarts).
  const double c_dt = c * dt;
  stage_dp_.resize(dp_.size());
  for (std::size_t i = 0; i < dp_.size(); ++i) stage_dp_[i] = c * dp_[i];
  predicted_flux(w, c_dt, p, stage_flux_);
  const int iterations = correct(w, stage_flux_, c_dt / options_.density, stage_dp_).iterations;
  if (auto* bc = options_.boundary.get()) bc->hold_outlets(w), bc->impose(w, t);
  // The stage's convective flux: the projected flux, with the scheme's face value in place of
  // the projection's where they differ (as F_1 of convective_flux()).
  if ((options_.scheme == ConvectionKind::central4) != static_cast<bool>(order4_)) {
    scheme_flux(w, flux_offset_);
    for (std::size_t e = 0; e < stage_flux_.size(); ++e) stage_flux_[e] += flux_offset_[e];
    projection_flux(w, flux_offset_);
    for (std::size_t e = 0; e < stage_flux_.size(); ++e) stage_flux_[e] -= flux_offset_[e];
  }
  return iterations;
}

StepReport ProjectionRK4::step(FlowState& state, double dt) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw std::invalid_argument("flow::ProjectionRK4::step: time step " + std::to_string(dt) +
                                " is not a positive finite number");
  const int n = mesh_.num_local();
  if (state.velocity.size() != static_cast<std::size_t>(n) ||
      state.pressure.size() != static_cast<std::size_t>(n))
    throw std::invalid_argument("flow::ProjectionRK4::step: state has " +
                                std::to_string(state.velocity.size()) + " velocities and " +
                                std::to_string(state.pressure.size()) + " pressures for " +
                                std::to_string(n) + " local nodes");
  const double rho = options_.density;
  auto* bc = options_.boundary.get();
  if (bc && bc->has_pressure_outlet() && poisson_.singular())
    throw std::logic_error(
        "flow::ProjectionRK4: pressure outlets need poisson.dirichlet = "
        "BoundaryConditions::pressure_dirichlet()");
  // Predictor with the old pressure gradient, fixed over the stages.
  pressure_gradient(state.pressure, grad_p_);
  if (options_.damp_pressure_increment) {
    // The damping acts on theta (p^n - p^{n-1}) = theta dp_ (checkpointed: bitwise restarts):
    // add_damping's share of p^n less that of p^n - theta dp_ (previous_p_). On a pressure mode
    // the wide operators do not see, the damping sets a_{n+1} = a_n - theta (a_n - a_{n-1}):
    // roots 1 (a steady mode stays, as without damping) and -theta. theta = 1 is a neutral
    // period-2 oscillation (a closed-valve hold diverged at t = 0.02 s with it); theta = 1/2
    // halves it every step.
    constexpr double theta = 0.5;
    previous_p_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) previous_p_[i] = state.pressure[i] - theta * dp_[i];
    pressure_gradient(previous_p_, grad_previous_p_);
  }
  const EdgeField& first_flux = convective_flux(state.velocity);  // also sets flux_offset_
  stage_ = state.velocity;
  StepReport report;
  const bool accumulate = !rk_.last_stage_only();
  for (int k = 0; k < 4; ++k) {
    // R(w_k) at t^n + c_k dt starts the update to w_{k+1} (v* for k = 3) at t^n + c' dt.
    const double c_next = rk_.update_coefficient(k), t_next = state.time + c_next * dt;
    if (bc && accumulate) {
      if (k == 0) stage_sum_.assign(static_cast<std::size_t>(n), Eigen::Vector3d::Zero());
      for (int i = 0; i < n; ++i) stage_sum_[i] += rk_.b[k] * stage_[i];
    }
    if (bc)
      bc->advect_outlets(k == 3 && accumulate ? stage_sum_ : stage_, state.velocity, t_next,
                         c_next * dt);
    if (k > 0 && !options_.project_stages) {
      scheme_flux(stage_, stage_flux_);
      for (std::size_t e = 0; e < stage_flux_.size(); ++e) stage_flux_[e] += flux_offset_[e];
    }
    // central4's face flux of stage_ (scheme_flux, or convective_flux at k = 0 on a copy of
    // the same velocity) has just left gradient(stage_) in grad_flux_.
    stage_gradient_known_ = options_.scheme == ConvectionKind::central4 && !options_.project_stages;
    momentum_rhs(stage_, k > 0 ? stage_flux_ : first_flux, rhs_, k);
    stage_gradient_known_ = false;  // laminar inviscid runs do not take it
    if (body_force_) {
      force_.resize(static_cast<std::size_t>(n));
      body_force_(k, state.time + rk_.c[k] * dt, stage_, force_);
      for (int i = 0; i < n; ++i) rhs_[i] += force_[i] / rho;
    }
    if (accumulate) {
      if (k == 0) rhs_sum_.assign(static_cast<std::size_t>(n), Eigen::Vector3d::Zero());
      for (int i = 0; i < n; ++i) rhs_sum_[i] += rk_.b[k] * rhs_[i];
    }
    const VectorField& r = k == 3 && accumulate ? rhs_sum_ : rhs_;
    for (int i = 0; i < n; ++i)
      stage_[i] = state.velocity[i] + c_next * dt * (r[i] - grad_p_[i] / rho);
    if (bc) bc->impose(stage_, t_next);  // v* is mass-corrected too
    if (options_.project_stages && k < 3)
      report.stage_poisson_iterations += project_stage(stage_, c_next, dt, t_next, state.pressure);
  }
  // Projection: lap(dp) = rho div(v*) / dt, warm-started from the previous increment, with the
  // divergence of the predicted face flux F* = P_p(v*) (+ the damping flux, predicted_flux).
  predicted_flux(stage_, dt, state.pressure, flux_);
  if (lumped_) lumped_->guess_increment(dp_);
  report.poisson = correct(stage_, flux_, dt / rho, dp_);
  if (lumped_) lumped_->couple(stage_, flux_, dp_, poisson_weights_, dt, dt / rho, state.time + dt);
  for (int i = 0; i < n; ++i) {
    state.velocity[i] = stage_[i];
    state.pressure[i] += dp_[i];
  }
  // Outlet nodes keep their corrected values (Neumann dp: the correction is part of the
  // projection there); Dirichlet values are restored and the mass is corrected again.
  if (bc) bc->hold_outlets(state.velocity), bc->impose(state.velocity, state.time + dt);
  if (lumped_) lumped_->finish(state.velocity, state.pressure, dt);
  state.time += dt;
  flux_velocity_ = state.velocity;
  projection_divergence(state.velocity, div_);
  double worst = 0, speed = 0;
  for (int i = 0; i < mesh_.num_owned; ++i) {
    worst = std::max(worst, std::abs(div_[i]));
    speed = std::max(speed, state.velocity[i].norm());
  }
  report.max_divergence = mesh_.comm.max(worst);
  const double max_speed = mesh_.comm.max(speed);
  std::tie(report.divergence_number, report.divergence_position) = divergence_peak({}, max_speed);
  if (bc) {
    bc->velocity_dirichlet(velocity_held_);
    std::tie(report.free_divergence_number, report.free_divergence_position) =
        divergence_peak(velocity_held_, max_speed);
  } else {
    report.free_divergence_number = report.divergence_number;
    report.free_divergence_position = report.divergence_position;
  }
  return report;
}

std::pair<double, Eigen::Vector3d> ProjectionRK4::divergence_peak(const std::vector<char>& skip,
                                                                  double max_speed) const {
  struct {
    double value;
    int rank;
  } worst{0.0, mesh_.comm.rank()};
  int worst_node = -1;
  for (int i = 0; i < mesh_.num_owned; ++i) {
    if (!skip.empty() && skip[i]) continue;
    // h = cbrt(volume) of the dual metrics: no cube root per node and step.
    if (const double w = std::abs(div_[i]) * mesh_.h[i]; w > worst.value)
      worst.value = w, worst_node = i;
  }
  // The rank holding the maximum (the lowest on a tie) sends its node's position, so that a run
  // can say where its projection is worst.
  VALSALVA_MPI(
      MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, mesh_.comm.get()));
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  if (worst.rank == mesh_.comm.rank() && worst_node >= 0) position = mesh_.position[worst_node];
  VALSALVA_MPI(MPI_Bcast(position.data(), 3, MPI_DOUBLE, worst.rank, mesh_.comm.get()));
  return {max_speed > 0 ? worst.value / max_speed : 0.0, position};
}

void ProjectionRK4::total_viscosity() {
  const std::size_t n = grad_u_.size();
  nu_eff_.resize(n);
  if (rheology_) {
    const double rho = options_.density;
    for (std::size_t i = 0; i < n; ++i)
      nu_eff_[i] = apparent_viscosity(options_.rheology, shear_rate(grad_u_[i])) / rho;
  } else {
    nu_eff_.assign(n, options_.viscosity);
  }
  if (options_.subgrid_viscosity && nu_sgs_.size() == n)
    for (std::size_t i = 0; i < n; ++i) nu_eff_[i] += nu_sgs_[i];
}

const ScalarField& ProjectionRK4::viscosity_field(const VectorField& u) {
  if (!rheology_)
    throw std::logic_error("flow::ProjectionRK4::viscosity_field without a non-Newtonian fluid");
  gradient(mesh_, u, grad_u_);
  total_viscosity();
  return nu_eff_;
}

double ProjectionRK4::max_subgrid_viscosity() const {
  double worst = 0;
  for (int i = 0; i < mesh_.num_owned && !nu_sgs_.empty(); ++i) worst = std::max(worst, nu_sgs_[i]);
  return mesh_.comm.max(worst);
}

}  // namespace valsalva::flow
