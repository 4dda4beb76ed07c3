// ITBM coupling; see immersed_structure.hpp.
#include "ibm/immersed_structure.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include "ibm/ib_stability.hpp"
#include "ibm/implicit_markers.hpp"

namespace valsalva::ibm {

namespace {

std::span<Eigen::Vector3d> as_points(Eigen::Matrix3Xd& m) {
  return {reinterpret_cast<Eigen::Vector3d*>(m.data()), static_cast<std::size_t>(m.cols())};
}

}  // namespace

ImmersedStructure::ImmersedStructure(mesh::LocalMesh& mesh, ImmersedOptions options)
    : mesh_(mesh),
      options_(options),
      transfer_(mesh, options.transfer),
      rk_(flow::tableau(options.time_scheme)) {
  if (!(options_.fluid_density > 0))
    throw std::invalid_argument(fmt::format(
        "ibm::ImmersedStructure: fluid density must be > 0 (got {})", options_.fluid_density));
}

int ImmersedStructure::add_body(const structure::SolidMesh& mesh,
                                const structure::Material& material, BodySpec spec) {
  bodies_.push_back(std::make_unique<ImmersedBody>(mesh, material, std::move(spec)));
  // Every rank holds the whole structure: the ranks split its contact search.
  if (mesh_.comm.size() > 1 && bodies_.back()->has_contact())
    bodies_.back()->share_contact(
        {mesh_.comm.rank(), mesh_.comm.size()},
        [comm = &mesh_.comm](std::span<double> v) { comm->sum_in_place(v); });
  const int first = num_markers(), n = mesh.num_nodes();
  first_.push_back(first);
  std::vector<char> fixed(n, 0);
  for (int a : bodies_.back()->fixed_nodes()) fixed[a] = 1;
  for (int a = 0; a < n; ++a)
    if (!fixed[a]) coupled_.push_back(first + a);
  auto grow = [&](Eigen::Matrix3Xd& m) { m.conservativeResize(3, first + n); };
  for (auto* m : {&x_, &x_n_, &x_stage_, &velocity_, &force_, &last_displacement_}) grow(*m);
  x_.middleCols(first, n) = mesh.X;
  velocity_.middleCols(first, n).setZero();
  force_.middleCols(first, n).setZero();
  last_displacement_.middleCols(first, n).setZero();
  dt_max_ = -1;
  return static_cast<int>(bodies_.size()) - 1;
}

void ImmersedStructure::set_positions(const Eigen::Matrix3Xd& x) {
  if (x.cols() != x_.cols())
    throw std::invalid_argument(fmt::format(
        "ibm::ImmersedStructure::set_positions: {} positions for {} markers", x.cols(), x_.cols()));
  x_ = x;
  dt_max_ = -1;
}

void ImmersedStructure::set_last_displacement(const Eigen::Matrix3Xd& d) {
  if (d.cols() != x_.cols())
    throw std::invalid_argument(
        fmt::format("ibm::ImmersedStructure::set_last_displacement: {} columns for {} markers",
                    d.cols(), x_.cols()));
  last_displacement_ = d;
}

flow::BodyForce ImmersedStructure::body_force() {
  return [this](int stage, double t, const flow::VectorField& u, flow::VectorField& f) {
    stage_force(stage, t, u, f);
  };
}

void ImmersedStructure::gather(const Eigen::Matrix3Xd& all, Eigen::Matrix3Xd& coupled) const {
  coupled.resize(3, static_cast<long>(coupled_.size()));
  for (std::size_t m = 0; m < coupled_.size(); ++m) coupled.col(long(m)) = all.col(coupled_[m]);
}

void ImmersedStructure::locate(const Eigen::Matrix3Xd& x) {
  gather(x, wrapped_);
  if (options_.box)
    for (int a = 0; a < wrapped_.cols(); ++a)
      wrapped_.col(a) = wrap_into(*options_.box, wrapped_.col(a));
  transfer_.relocate(as_points(wrapped_));
}

void ImmersedStructure::restore_location(const std::vector<Eigen::Vector3d>& located_at) {
  if (located_at.size() != coupled_.size())
    throw std::invalid_argument(
        fmt::format("ibm::ImmersedStructure::restore_location: {} positions for {} coupled markers",
                    located_at.size(), coupled_.size()));
  transfer_.locate(located_at);
}

void ImmersedStructure::compute_forces(const Eigen::Matrix3Xd& x) {
  min_det_ = 1e300;
  for (int b = 0; b < num_bodies(); ++b) {
    const double det = bodies_[b]->forces(x.middleCols(first_[b], count(b)),
                                          force_.middleCols(first_[b], count(b)));
    min_det_ = std::min(min_det_, det);
    if (!(det > 0)) {
      const auto [e, worst] = bodies_[b]->solid_forces().worst_element(
          Eigen::Matrix3Xd(x.middleCols(first_[b], count(b))));
      throw std::runtime_error(fmt::format(
          "ibm::ImmersedStructure: body '{}' has an inverted element {} (det F = {:.3e}); the "
          "coupling is unstable or the time step too large (last stable_time_step {:.3e} s)",
          bodies_[b]->spec().name, e, worst, dt_max_));
    }
  }
}

void ImmersedStructure::spread(flow::VectorField& density) {
  density.resize(static_cast<std::size_t>(mesh_.num_local()));
  gather(force_, coupled_force_);
  transfer_.spread(as_points(coupled_force_), density);
}

void ImmersedStructure::interpolate(const flow::VectorField& u) {
  u_copy_ = u;  // interpolate() refreshes ghosts in place; the stage velocity is const
  coupled_velocity_.resize(3, static_cast<long>(coupled_.size()));
  transfer_.interpolate(std::span<Eigen::Vector3d>(u_copy_), as_points(coupled_velocity_));
  for (std::size_t m = 0; m < coupled_.size(); ++m)
    velocity_.col(coupled_[m]) = coupled_velocity_.col(long(m));  // fixed nodes keep 0
}

void ImmersedStructure::stage_force(int stage, double stage_time,
                                    const flow::VectorField& stage_velocity,
                                    flow::VectorField& force_density) {
  if (stage == 0) {
    t_n_ = stage_time;
    x_n_ = x_;
  }
  if (options_.mode == CouplingMode::implicit) {
    if (stage == 0) {
      // F(X^n) - K dX^{n-1}: the force linearly extrapolated to t^{n+1} (implicit_markers.hpp).
      locate(x_n_);
      compute_forces(x_n_);
      assemble_stiffness(x_n_);
      force_n_ = force_;
      for (int b = 0; b < num_bodies(); ++b) {
        const int n = count(b);
        Eigen::Map<const Eigen::VectorXd> d(last_displacement_.data() + 3 * first_[b], 3 * n);
        Eigen::Map<Eigen::VectorXd> f(force_.data() + 3 * first_[b], 3 * n);
        f -= stiffness_[b] * d;
      }
      spread(held_force_);
    }
    force_density = held_force_;
    return;
  }
  if (options_.mode == CouplingMode::per_step) {
    if (stage == 0) {
      locate(x_n_);
      compute_forces(x_n_);
      spread(held_force_);
    }
    force_density = held_force_;
    return;
  }
  // X_k = X^n + c_k dt U_{k-1}, c_k dt = t_k - t^n.
  if (stage == 0)
    x_stage_ = x_n_;
  else
    x_stage_ = x_n_ + (stage_time - t_n_) * velocity_;
  locate(x_stage_);
  compute_forces(x_stage_);
  spread(force_density);
  interpolate(stage_velocity);
  if (!rk_.last_stage_only()) {
    if (stage == 0) velocity_sum_.setZero(3, velocity_.cols());
    velocity_sum_ += rk_.b[stage] * velocity_;
  }
}

void ImmersedStructure::finish_step(flow::FlowState& state) {
  finish(state, &state);
}

void ImmersedStructure::finish_step(const flow::FlowState& state) {
  finish(state, nullptr);
}

void ImmersedStructure::finish(const flow::FlowState& state, flow::FlowState* correctable) {
  const double dt = state.time - t_n_;
  if (!(dt > 0))
    throw std::logic_error(
        "ibm::ImmersedStructure::finish_step: called without a flow step through the body-force "
        "hook (time did not advance)");
  if (options_.mode == CouplingMode::implicit) {
    if (options_.implicit_variant == ImplicitVariant::backward_euler && !correctable)
      throw std::logic_error(
          "ibm::ImmersedStructure::finish_step: implicit_variant backward_euler corrects the "
          "fluid velocity and needs the mutable flow state");
    interpolate(state.velocity);  // the transfer is still located at X^n
    implicit_finish(dt, correctable);
    return;
  }
  if (options_.mode == CouplingMode::per_step) {
    // Transfer is still located at X^n: U(u^{n+1}, X^n).
    interpolate(state.velocity);
  }
  // X^{n+1} = X^n + dt sum_k b_k U_k (per_step: U(u^{n+1}, X^n) alone).
  if (options_.mode == CouplingMode::per_stage && !rk_.last_stage_only()) velocity_ = velocity_sum_;
  x_ = x_n_ + dt * velocity_;
}

void ImmersedStructure::current_force_density(flow::VectorField& density) {
  locate(x_);
  compute_forces(x_);
  spread(density);
}

void ImmersedStructure::support_nodes(std::vector<char>& nodes) {
  locate(x_);
  const int n = mesh_.num_local();
  std::vector<double> reach(static_cast<std::size_t>(n));
  transfer_.support_reach(reach);
  nodes.assign(static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n; ++j) nodes[j] = reach[j] > 0;
}

void ImmersedStructure::assemble_stiffness(const Eigen::Matrix3Xd& x) {
  stiffness_.resize(bodies_.size());
  for (int b = 0; b < num_bodies(); ++b)
    bodies_[b]->stiffness(Eigen::Matrix3Xd(x.middleCols(first_[b], count(b))), stiffness_[b]);
  stiffness_in_ = Eigen::Matrix3Xd::Zero(3, num_markers());
  stiffness_out_.resize(3, num_markers());
}

void ImmersedStructure::apply_coupled_stiffness(const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& kv) {
  for (std::size_t m = 0; m < coupled_.size(); ++m) stiffness_in_.col(coupled_[m]) = v.col(long(m));
  for (int b = 0; b < num_bodies(); ++b) {
    const int n = count(b);
    Eigen::Map<const Eigen::VectorXd> vb(stiffness_in_.data() + 3 * first_[b], 3 * n);
    Eigen::Map<Eigen::VectorXd> kb(stiffness_out_.data() + 3 * first_[b], 3 * n);
    kb = stiffness_[b] * vb;
  }
  gather(stiffness_out_, kv);
}

void ImmersedStructure::coupled_response(const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& out,
                                         bool projected) {
  Eigen::Matrix3Xd kv;
  apply_coupled_stiffness(v, kv);
  response_density_.resize(static_cast<std::size_t>(mesh_.num_local()));
  transfer_.spread(as_points(kv), response_density_);
  if (projected) {
    response_potential_.resize(response_density_.size(), 0.0);
    projector_(response_density_, response_potential_);
  }
  out.resize(3, v.cols());
  transfer_.interpolate(std::span<Eigen::Vector3d>(response_density_), as_points(out));
}

namespace {

// X with the markers `coupled` (indices into X's columns) displaced by d (3 x coupled markers).
Eigen::Matrix3Xd displaced(Eigen::Matrix3Xd x, const std::vector<int>& coupled,
                           const Eigen::Matrix3Xd& d) {
  for (std::size_t m = 0; m < coupled.size(); ++m) x.col(coupled[m]) += d.col(long(m));
  return x;
}

}  // namespace

Eigen::Matrix3Xd ImmersedStructure::lagged_residual(const Eigen::Matrix3Xd& b, double c,
                                                    const Eigen::Matrix3Xd& d) {
  Eigen::Matrix3Xd difference, response;
  compute_forces(displaced(x_n_, coupled_, d));
  gather(Eigen::Matrix3Xd(force_ - force_n_), difference);
  response_density_.resize(static_cast<std::size_t>(mesh_.num_local()));
  transfer_.spread(as_points(difference), response_density_);
  response.resize(3, difference.cols());
  transfer_.interpolate(std::span<Eigen::Vector3d>(response_density_), as_points(response));
  return b + c * response - d;
}

void ImmersedStructure::newton_lagged(const Eigen::Matrix3Xd& b, double c, ImplicitSolve& solve) {
  // The lagged solve linearises dX = dt U + c A [F(X^n + dX) - F(X^n)] at X^n; Newton
  // iterations on that equation (A kept at X^n, K re-assembled at each iterate) remove the
  // linearisation's error, which sets the variant's stability limit on strained solids. Each
  // update is halved until the residual falls and no element inverts (a backtracking line
  // search: Nocedal & Wright, Numerical Optimization, 2006, sect. 3.1).
  const auto apply = [this](const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& kv) {
    apply_coupled_stiffness(v, kv);
  };
  auto& d = solve.displacement;
  Eigen::Matrix3Xd residual;
  try {
    residual = lagged_residual(b, c, d);
  } catch (const std::runtime_error&) {  // the linearised step inverts an element: from X^n
    d.setZero();
    residual = b;
  }
  while (newton_iterations_ < options_.implicit_newton_iterations) {
    assemble_stiffness(displaced(x_n_, coupled_, d));
    const auto update = implicit_marker_displacement(transfer_, apply, residual, c);
    solve.iterations += update.iterations;
    ++newton_iterations_;
    double step = -1;
    for (double alpha = 1; alpha > 1e-3 && step < 0; alpha *= 0.5) {
      const Eigen::Matrix3Xd trial = d + alpha * update.displacement;
      Eigen::Matrix3Xd trial_residual;
      try {
        trial_residual = lagged_residual(b, c, trial);
      } catch (const std::runtime_error&) {  // an inverted element: the same on every rank
        continue;
      }
      if (trial_residual.norm() < residual.norm()) {
        step = alpha * update.displacement.norm();
        d = trial;
        residual = trial_residual;
      }
    }
    if (step < 0 || step <= options_.implicit_newton_tolerance * d.norm()) break;
  }
  // The forces (and min det F) of the accepted iterate, not of the last rejected trial.
  compute_forces(displaced(x_n_, coupled_, d));
}

void ImmersedStructure::implicit_finish(double dt, flow::FlowState* state) {
  // (I + dt^2/rho A K) dX = dt U(u^{n+1}, X^n) [+ c A K dX^{n-1}] on the coupled markers, with A
  // and K at X^n (ImplicitVariant).
  const auto apply = [this](const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& kv) {
    apply_coupled_stiffness(v, kv);
  };
  const double c = dt * dt / options_.fluid_density;
  const auto variant = options_.implicit_variant;
  const bool projected = variant == ImplicitVariant::backward_euler;
  if (projected && !projector_)
    throw std::logic_error(
        "ibm::ImmersedStructure: implicit_variant backward_euler without a projector "
        "(set_projector)");
  Eigen::Matrix3Xd b = dt * coupled_velocity_;
  Eigen::Matrix3Xd previous;
  if (variant != ImplicitVariant::lagged) {
    gather(last_displacement_, previous);
    Eigen::Matrix3Xd response;
    coupled_response(previous, response, projected);
    b += c * response;
  }
  ImplicitSolve solve;
  if (projected) {
    // The unprojected solve as the initial guess of the projected one (Ceniceros, Fisher & Roma
    // 2009 precondition with it).
    const auto guess = implicit_marker_displacement(transfer_, apply, b, c);
    solve = implicit_marker_displacement(transfer_, apply, b, c, 1e-8, 1000, &projector_,
                                         &guess.displacement);
  } else {
    solve = implicit_marker_displacement(transfer_, apply, b, c);
  }
  newton_iterations_ = 1;
  if (variant == ImplicitVariant::lagged && options_.implicit_newton_iterations > 1)
    newton_lagged(b, c, solve);
  implicit_iterations_ = solve.iterations;
  if (projected) {
    // The flow step felt -K dX^{n-1}; backward Euler has it feel -K dX: the velocity and the
    // pressure get the flow's response to -K (dX - dX^{n-1}) held over the step, u += dt/rho P
    // Spread(-K (dX - dX^{n-1})) and p += rho/dt q of that projection (the incremental pressure
    // is part of the flow's state: without it the next steps feel the force change again).
    Eigen::Matrix3Xd change = solve.displacement - previous, kv;
    apply_coupled_stiffness(change, kv);
    response_density_.resize(static_cast<std::size_t>(mesh_.num_local()));
    transfer_.spread(as_points(kv), response_density_);
    const double scale = dt / options_.fluid_density;
    for (auto& f : response_density_) f *= -scale;
    flow::ScalarField q(response_density_.size(), 0.0);
    projector_(response_density_, q);
    for (std::size_t i = 0; i < response_density_.size(); ++i) {
      state->velocity[i] += response_density_[i];
      state->pressure[i] += q[i] / scale;
    }
  }
  last_displacement_.setZero();
  for (std::size_t m = 0; m < coupled_.size(); ++m)
    last_displacement_.col(coupled_[m]) = solve.displacement.col(long(m));
  x_ = x_n_ + last_displacement_;
  velocity_ = last_displacement_ / dt;
}

double ImmersedStructure::stable_time_step() {
  if (options_.mode == CouplingMode::implicit) {
    dt_max_ = std::numeric_limits<double>::infinity();  // no bound of its own
    return dt_max_;
  }
  locate(x_);
  assemble_stiffness(x_);
  const auto apply = [this](const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& kv) {
    apply_coupled_stiffness(v, kv);
  };
  const auto eig = kernel_mapped_stiffness_eigenvalue(transfer_, apply);
  dt_max_ = coupling_time_step_bound(eig.lambda, options_.fluid_density,
                                     options_.mode == CouplingMode::per_stage);
  return dt_max_;
}

void ImmersedStructure::check_time_step(double dt) {
  if (dt_max_ < 0) stable_time_step();
  if (dt > options_.stability_safety * dt_max_)
    throw std::runtime_error(fmt::format(
        "ibm::ImmersedStructure: time step {:.4e} s exceeds the stability limit {:.4e} s of the "
        "explicit immersed-boundary coupling ({} mode; safety factor {}): the limit is "
        "{} / omega with omega^2 = lambda_max(Interp Spread K) / rho, set by the solid stiffness "
        "and the fluid mesh size at the markers. Lower the time step, soften or coarsen the "
        "solid, or widen the kernel",
        dt, options_.stability_safety * dt_max_,
        options_.mode == CouplingMode::per_stage ? "per-stage" : "per-step",
        options_.stability_safety, options_.mode == CouplingMode::per_stage ? "2 sqrt(2)" : "2"));
}

Eigen::Vector3d ImmersedStructure::fixed_force(int b) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int a : bodies_[b]->fixed_nodes()) sum += force_.col(first_[b] + a);
  return sum;
}

Eigen::Vector3d ImmersedStructure::total_force(int b) const {
  return force_.middleCols(first_[b], count(b)).rowwise().sum() - fixed_force(b);
}

Eigen::Vector3d ImmersedStructure::tether_force(int b) const {
  if (bodies_[b]->spec().clamp == Clamp::fixed) return -fixed_force(b);
  return bodies_[b]->tether_force(x_.middleCols(first_[b], count(b)));
}

}  // namespace valsalva::ibm
