// Lumped outlets and their implicit coupling to the projection; see lumped_outlets.hpp.
#include "flow/lumped_outlets.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace valsalva::flow {

DistalWeights distal_weights(double h) {
  DistalWeights w;
  w.decay = std::exp(-h);
  if (h < 1e-3) {
    // w_0 = sum_k (-1)^(k+1) k h^k / (k+1)!, w_1 = sum_k (-1)^(k+1) h^k / (k+1)! (k >= 1): the
    // closed forms lose digits to cancellation as h -> 0.
    double term = 1;  // h^k / (k+1)!
    for (int k = 1; k <= 8; ++k) {
      term *= h / (k + 1);
      const double sign = k % 2 ? 1.0 : -1.0;
      w.w0 += sign * k * term;
      w.w1 += sign * term;
    }
    return w;
  }
  const double phi1 = -std::expm1(-h) / h;  // (1 - e^{-h}) / h
  w.w0 = phi1 - w.decay;
  w.w1 = 1 - phi1;
  return w;
}

OutletStep outlet_step(const BoundarySpec& spec, const LumpedState& state, double dt,
                       double t_next) {
  switch (spec.type) {
    case BoundaryType::resistance_outlet:
      return {spec.pressure, spec.resistance};
    case BoundaryType::pressure_inlet:
      return {spec.inlet_pressure(t_next), 0};
    case BoundaryType::elastance_inlet: {
      const double e = spec.elastance(t_next);
      return {e * (state.distal + 0.5 * dt * state.flux - spec.rest_volume), 0.5 * dt * e};
    }
    default: {
      const auto w = distal_weights(dt / (spec.distal_resistance * spec.capacitance));
      return {w.decay * state.distal + spec.distal_resistance * w.w0 * state.flux,
              spec.resistance + spec.distal_resistance * w.w1};
    }
  }
}

double distal_after(const BoundarySpec& spec, const LumpedState& state, double q_next, double dt) {
  if (spec.type == BoundaryType::elastance_inlet)
    return state.distal + 0.5 * dt * (state.flux + q_next);
  if (spec.type != BoundaryType::rcr_outlet) return 0;
  const auto w = distal_weights(dt / (spec.distal_resistance * spec.capacitance));
  return w.decay * state.distal + spec.distal_resistance * (w.w0 * state.flux + w.w1 * q_next);
}

VenousStep venous_step(const BoundarySpec& rcr, const LumpedState& state, double dt) {
  const double c = rcr.capacitance, rd = rcr.distal_resistance;
  const auto w = distal_weights(dt / (rd * c));
  return {0.5 * dt * state.flux - c * ((w.decay - 1) * state.distal + rd * w.w0 * state.flux),
          0.5 * dt - c * rd * w.w1};
}

double outlet_pressure(const BoundarySpec& spec, double q, double distal, double t) {
  switch (spec.type) {
    case BoundaryType::resistance_outlet:
      return spec.pressure + spec.resistance * q;
    case BoundaryType::pressure_inlet:
      return spec.inlet_pressure(t);
    case BoundaryType::elastance_inlet:
      return spec.elastance(t) * (distal - spec.rest_volume);
    default:
      return distal + spec.resistance * q;
  }
}

const char* distal_column(BoundaryType type) {
  return type == BoundaryType::rcr_outlet        ? "distal_pressure_"
         : type == BoundaryType::elastance_inlet ? "volume_"
                                                 : nullptr;
}

LumpedOutlets::LumpedOutlets(const mesh::LocalMesh& mesh, BoundaryConditions& bc,
                             const Solve& solve, const Gradient& gradient)
    : mesh_(mesh), bc_(bc) {
  const auto& specs = bc.specs();
  for (std::size_t s = 0; s < specs.size(); ++s)
    if (lumped_type(specs[s].type)) {
      patches_.push_back(bc.spec_patches()[s]);
      spec_.push_back(static_cast<int>(s));
    }
  const int n = count();
  const auto& owner = bc.pressure_owner();
  const ScalarField zero(mesh.num_local(), 0.0);
  for (int k = 0; k < n; ++k) {
    // phi_k: harmonic, 1 on the nodes outlet k owns, 0 on every other Dirichlet node.
    ScalarField phi(mesh.num_local(), 0.0);
    int nodes = 0;
    for (int j = 0; j < mesh.num_local(); ++j)
      if (owner[j] == patches_[k]) phi[j] = 1, nodes += j < mesh.num_owned;
    if (mesh.comm.sum(static_cast<std::int64_t>(nodes)) == 0)
      throw std::invalid_argument("lumped outlet '" + mesh.patch_names[patches_[k]] +
                                  "': every node of the patch belongs to a fixed "
                                  "pressure_outlet or to another lumped outlet");
    solve(zero, phi);
    VectorField grad;
    gradient(phi, grad);
    phi_.push_back(std::move(phi));
    grad_phi_.push_back(std::move(grad));
  }
  for (int k = 0; k < n; ++k) {
    int source = -1;
    for (int r = 0; r < n; ++r)
      if (!spec(k).venous_return.empty() && spec(r).patch == spec(k).venous_return) source = r;
    source_.push_back(source);
  }
  states_.assign(n, LumpedState{});
  steps_.assign(n, OutletStep{});
  response_.setZero(n, n);
  system_.setZero(n, n);
  rhs_.setZero(n);
  delta_.setZero(n);
  used_.assign(n, 0.0);
}

void LumpedOutlets::start(const VectorField& velocity, ScalarField& pressure, double t) {
  const auto q = bc_.patch_fluxes(velocity);
  for (int k = 0; k < count(); ++k) {
    auto& s = states_[k];
    s.flux = q[patches_[k]];
    const auto type = spec(k).type;
    s.distal = type == BoundaryType::rcr_outlet        ? spec(k).distal_pressure
               : type == BoundaryType::elastance_inlet ? spec(k).volume
                                                       : 0.0;
    // The pressure of the fluid at rest (p0, p_d(0)): the initial velocity's flux split is the
    // mass correction's, not the flow's, and its R Q^0 put 7 kPa between the two outlets of
    // validation/rcr_outlet/rcr_split.toml at R_d = 1e10 Pa s/m3, which blew the first step up;
    // the first step's implicit solve makes P and Q consistent.
    s.pressure = outlet_pressure(spec(k), 0.0, s.distal, t);
    s.increment = 0;
    bc_.set_outlet_pressure(patches_[k], s.pressure);
    // The harmonic lift P^0 phi_k, so that the first step's grad p^n does not see P^0 jump over
    // one cell at the outlet.
    for (int i = 0; i < mesh_.num_local(); ++i) pressure[i] += s.pressure * phi_[k][i];
  }
  bc_.impose_pressure(pressure);
}

std::vector<double> LumpedOutlets::saved() const {
  std::vector<double> v;
  for (const auto& s : states_) v.insert(v.end(), {s.flux, s.pressure, s.distal, s.increment});
  return v;
}

void LumpedOutlets::restore(const std::vector<double>& v) {
  if (v.size() != states_.size() * lumped_state_size)
    throw std::invalid_argument("flow::LumpedOutlets::restore: " + std::to_string(v.size()) +
                                " values for " + std::to_string(count()) + " lumped outlets");
  for (std::size_t k = 0; k < states_.size(); ++k) {
    const double* x = &v[lumped_state_size * k];
    states_[k] = {x[0], x[1], x[2], x[3]};
    bc_.set_outlet_pressure(patches_[k], states_[k].pressure);
  }
}

void LumpedOutlets::guess_increment(ScalarField& dp) const {
  const auto& owner = bc_.pressure_owner();
  for (int k = 0; k < count(); ++k)
    for (int j = 0; j < mesh_.num_local(); ++j)
      if (owner[j] == patches_[k]) dp[j] = states_[k].increment;
}

void LumpedOutlets::couple(VectorField& u, EdgeField& flux, ScalarField& dp,
                           const std::vector<double>& weights, double dt, double dt_over_rho,
                           double t_next) {
  const int n = count();
  bc_.hold_outlets(u);
  bc_.impose(u, t_next);
  const auto q0 = bc_.patch_fluxes(u);
  for (int k = 0; k < n; ++k) {
    const auto r = bc_.flux_response(grad_phi_[k]);
    for (int j = 0; j < n; ++j) response_(j, k) = -dt_over_rho * r[patches_[j]];
  }
  for (int j = 0; j < n; ++j) {
    auto& step = steps_[j];
    step = outlet_step(spec(j), states_[j], dt, t_next);
    if (const int k = source_[j]; k >= 0) {
      const auto v = venous_step(spec(k), states_[k], dt);
      const double e = spec(j).elastance(t_next);
      step.offset += e * v.d0;
      step.source = k;
      step.cross = e * v.d1;
    }
    const auto& s = states_[j];
    // P^n + guess + delta_j = offset + slope (Q_0 + M delta)_j + cross (Q_0 + M delta)_source
    rhs_(j) = step.offset + step.slope * q0[patches_[j]] - s.pressure - s.increment;
    system_.row(j) = -step.slope * response_.row(j);
    if (step.source >= 0) {
      rhs_(j) += step.cross * q0[patches_[step.source]];
      system_.row(j) -= step.cross * response_.row(step.source);
    }
    system_(j, j) += 1;
  }
  delta_ = system_.partialPivLu().solve(rhs_);
  for (int j = 0; j < n; ++j) used_[j] = states_[j].pressure + states_[j].increment + delta_(j);
  for (int k = 0; k < n; ++k) {
    const double d = delta_(k);
    const auto& phi = phi_[k];
    const auto& g = grad_phi_[k];
    for (int i = 0; i < mesh_.num_local(); ++i) {
      u[i] -= (dt_over_rho * d) * g[i];
      dp[i] += d * phi[i];
    }
    add_compact_gradient(mesh_, weights, -dt_over_rho * d, phi, flux);
  }
}

void LumpedOutlets::finish(const VectorField& velocity, ScalarField& pressure, double dt) {
  const auto q = bc_.patch_fluxes(velocity);
  const int n = count();
  std::vector<double> q_next(n), distal(n);
  for (int k = 0; k < n; ++k) {
    q_next[k] = q[patches_[k]];
    distal[k] = distal_after(spec(k), states_[k], q_next[k], dt);
  }
  // Venous return: the volume the source's distal resistance passed, from its own update, so
  // that V + C p_d is conserved to round-off.
  for (int j = 0; j < n; ++j)
    if (const int k = source_[j]; k >= 0)
      distal[j] += 0.5 * dt * (states_[k].flux + q_next[k]) -
                   spec(k).capacitance * (distal[k] - states_[k].distal);
  mismatch_ = 0;
  for (int k = 0; k < n; ++k) {
    auto& s = states_[k];
    const auto& step = steps_[k];
    double p_next = step.offset + step.slope * q_next[k];
    if (step.source >= 0) p_next += step.cross * q_next[step.source];
    mismatch_ = std::max(mismatch_, std::abs(p_next - used_[k]));
    s.distal = distal[k];
    s.increment = p_next - s.pressure;
    s.pressure = p_next;
    s.flux = q_next[k];
    bc_.set_outlet_pressure(patches_[k], p_next);
  }
  bc_.impose_pressure(pressure);
}

}  // namespace valsalva::flow
