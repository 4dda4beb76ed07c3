// Projection + low-storage RK4 step; see projection_rk4.hpp.
#include "flow/projection_rk4.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "flow/viscous_stress.hpp"

namespace valsalva::flow {

ProjectionRK4::ProjectionRK4(const LocalMesh& mesh, ProjectionOptions options,
                             std::vector<double> poisson_weights)
    : mesh_(mesh),
      options_(options),
      weights_(flow::laplacian_weights(mesh)),
      poisson_weights_(poisson_weights.empty() ? weights_ : std::move(poisson_weights)),
      convection_(make_convection_scheme(options.scheme, mesh)),
      poisson_(mesh, poisson_weights_, options.poisson),
      dp_(mesh.num_local(), 0.0) {
  if (!(options.density > 0) || !(options.viscosity >= 0))
    throw std::invalid_argument("flow::ProjectionRK4: density must be > 0 (got " +
                                std::to_string(options.density) + ") and viscosity >= 0 (got " +
                                std::to_string(options.viscosity) + ")");
  if (options.fourth_order_operators) {
    if (options.subgrid_viscosity)
      throw std::invalid_argument(
          "flow::ProjectionRK4: the 4th-order operators have no full-stress (LES) viscous term; "
          "run an LES without fourth_order_operators");
    order4_ = std::make_unique<Order4Operators>(mesh, poisson_weights_);
  }
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

void ProjectionRK4::momentum_rhs(const VectorField& u, VectorField& rhs, int stage) {
  convection_->apply(u, conv_);
  if (options_.subgrid_viscosity) {
    // The gradient's ghosts are valid, so nu_sgs is computed on ghosts too: no exchange.
    gradient(mesh_, u, grad_u_);
    nu_sgs_.resize(grad_u_.size());
    options_.subgrid_viscosity(stage, grad_u_, nu_sgs_);
    nu_eff_.resize(nu_sgs_.size());
    for (std::size_t i = 0; i < nu_sgs_.size(); ++i) nu_eff_[i] = options_.viscosity + nu_sgs_[i];
    viscous_stress(mesh_, weights_, nu_eff_, u, grad_u_, rhs);
  } else if (options_.viscosity > 0) {
    gradient(mesh_, u, grad_u_);
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
    if (options_.viscosity > 0 || options_.subgrid_viscosity)
      options_.boundary->drop_outlet_viscous_flux(grad_u_, options_.viscosity, nu_sgs_, rhs);
  }
}

void ProjectionRK4::set_pressure_increment(const ScalarField& dp) {
  if (dp.size() != dp_.size())
    throw std::invalid_argument(
        "flow::ProjectionRK4::set_pressure_increment: " + std::to_string(dp.size()) +
        " values for " + std::to_string(dp_.size()) + " local nodes");
  dp_ = dp;
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

void ProjectionRK4::matrix_laplacian(const ScalarField& p, const VectorField& grad_p,
                                     ScalarField& out) const {
  // (1/V_j) [sum_k w_jk (p_k - p_j) + sum_faces grad p_j . A_j]: the hypre matrix's operator plus
  // the boundary-face flux that divergence(grad p) also contains, so that the damping term
  // carries no boundary flux (the Poisson problem is Neumann there).
  out.assign(mesh_.num_local(), 0.0);
  for (const auto& b : mesh_.boundary) out[b.node] += grad_p[b.node].dot(b.area);
  for (int e = 0; e < mesh_.num_owned_edges; ++e) {
    const auto [j, k] = mesh_.edges[e];
    const double f = poisson_weights_[e] * (p[k] - p[j]);
    out[j] += f;
    out[k] -= f;
  }
  for (int i = 0; i < mesh_.num_owned; ++i) out[i] /= mesh_.volume[i];
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
  stage_ = state.velocity;
  double alpha_prev = 0;  // the stage velocity stands at t^n + alpha_prev dt
  int stage = 0;
  for (double alpha : std::array{1.0 / 4, 1.0 / 3, 1.0 / 2, 1.0}) {
    if (bc) bc->advect_outlets(stage_, state.velocity, state.time + alpha * dt, alpha * dt);
    momentum_rhs(stage_, rhs_, stage);
    if (body_force_) {
      force_.resize(static_cast<std::size_t>(n));
      body_force_(stage, state.time + alpha_prev * dt, stage_, force_);
      for (int i = 0; i < n; ++i) rhs_[i] += force_[i] / rho;
    }
    alpha_prev = alpha;
    ++stage;
    for (int i = 0; i < n; ++i)
      stage_[i] = state.velocity[i] + alpha * dt * (rhs_[i] - grad_p_[i] / rho);
    if (bc) bc->impose(stage_, state.time + alpha * dt);  // v* is mass-corrected too
  }
  // Projection: lap(dp) = rho div(v*) / dt, warm-started from the previous increment.
  projection_divergence(stage_, div_);
  for (auto& d : div_) d *= rho / dt;
  if (bc && options_.pressure_damping) {
    // Pressure damping (Rhie & Chow, AIAA J. 21, 1983, in its node-centred form): the divergence
    // of v* takes the face-velocity correction dt/rho (avg(grad p^n) - grad p^n|_face), i.e.
    // f += div(grad p^n) - lap(p^n) with the wide divergence of the wide gradient and the
    // compact, linearly exact Laplacian of flow/operators.hpp. The odd-even pressure mode that
    // inlets and wall corners excite is invisible to the wide operators and otherwise stays
    // in the steady state; the term vanishes for linear pressure and is O(h^2) for smooth ones.
    // The compact Laplacian here must be the Poisson matrix's own operator (P1 weights on
    // tetrahedra): with the two-point Laplacian instead, the damping pumps energy into the
    // flow on tetrahedral meshes and a DFG cylinder run blew up in 15 steps at any dt.
    divergence(mesh_, grad_p_, div_grad_p_);
    matrix_laplacian(state.pressure, grad_p_, lap_p_);
    for (int i = 0; i < mesh_.num_owned; ++i) div_[i] += div_grad_p_[i] - lap_p_[i];
  }
  StepReport report;
  report.poisson = poisson_.solve(div_, dp_);
  pressure_gradient(dp_, grad_p_);
  for (int i = 0; i < n; ++i) {
    state.velocity[i] = stage_[i] - dt / rho * grad_p_[i];
    state.pressure[i] += dp_[i];
  }
  // Outlet nodes keep their corrected values (Neumann dp: the correction is part of the
  // projection there); Dirichlet values are restored and the mass is corrected again.
  if (bc) bc->hold_outlets(state.velocity), bc->impose(state.velocity, state.time + dt);
  state.time += dt;
  projection_divergence(state.velocity, div_);
  double worst = 0;
  for (int i = 0; i < mesh_.num_owned; ++i) worst = std::max(worst, std::abs(div_[i]));
  report.max_divergence = mesh_.comm.max(worst);
  return report;
}

double ProjectionRK4::max_subgrid_viscosity() const {
  double worst = 0;
  for (int i = 0; i < mesh_.num_owned && !nu_sgs_.empty(); ++i) worst = std::max(worst, nu_sgs_[i]);
  return mesh_.comm.max(worst);
}

}  // namespace valsalva::flow
