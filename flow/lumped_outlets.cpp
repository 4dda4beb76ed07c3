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

OutletStep outlet_step(const BoundarySpec& spec, const LumpedState& state, double dt) {
  if (spec.type == BoundaryType::resistance_outlet) return {spec.pressure, spec.resistance};
  const auto w = distal_weights(dt / (spec.distal_resistance * spec.capacitance));
  return {w.decay * state.distal + spec.distal_resistance * w.w0 * state.flux,
          spec.resistance + spec.distal_resistance * w.w1};
}

double distal_after(const BoundarySpec& spec, const LumpedState& state, double q_next, double dt) {
  if (spec.type != BoundaryType::rcr_outlet) return 0;
  const auto w = distal_weights(dt / (spec.distal_resistance * spec.capacitance));
  return w.decay * state.distal + spec.distal_resistance * (w.w0 * state.flux + w.w1 * q_next);
}

double outlet_pressure(const BoundarySpec& spec, double q, double distal) {
  return spec.type == BoundaryType::resistance_outlet ? spec.pressure + spec.resistance * q
                                                      : distal + spec.resistance * q;
}

LumpedOutlets::LumpedOutlets(const LocalMesh& mesh, BoundaryConditions& bc, const Solve& solve,
                             const Gradient& gradient)
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
  states_.assign(n, LumpedState{});
  steps_.assign(n, OutletStep{});
  response_.setZero(n, n);
  system_.setZero(n, n);
  rhs_.setZero(n);
  delta_.setZero(n);
  used_.assign(n, 0.0);
}

void LumpedOutlets::start(const VectorField& velocity, ScalarField& pressure) {
  const auto q = bc_.patch_fluxes(velocity);
  for (int k = 0; k < count(); ++k) {
    auto& s = states_[k];
    s.flux = q[patches_[k]];
    s.distal = spec(k).type == BoundaryType::rcr_outlet ? spec(k).distal_pressure : 0.0;
    // The pressure of the fluid at rest (p0, p_d(0)): the initial velocity's flux split is the
    // mass correction's, not the flow's, and its R Q^0 put 7 kPa between the two outlets of
    // validation/rcr_outlet/rcr_split.toml at R_d = 1e10 Pa s/m3, which blew the first step up;
    // the first step's implicit solve makes P and Q consistent.
    s.pressure = outlet_pressure(spec(k), 0.0, s.distal);
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
    steps_[j] = outlet_step(spec(j), states_[j], dt);
    const auto& s = states_[j];
    // P^n + guess + delta_j = offset + slope (Q_0 + M delta)
    rhs_(j) = steps_[j].offset + steps_[j].slope * q0[patches_[j]] - s.pressure - s.increment;
    system_.row(j) = -steps_[j].slope * response_.row(j);
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
  mismatch_ = 0;
  for (int k = 0; k < count(); ++k) {
    auto& s = states_[k];
    const double q_next = q[patches_[k]];
    const double p_next = steps_[k].offset + steps_[k].slope * q_next;
    mismatch_ = std::max(mismatch_, std::abs(p_next - used_[k]));
    s.distal = distal_after(spec(k), s, q_next, dt);
    s.increment = p_next - s.pressure;
    s.pressure = p_next;
    s.flux = q_next;
    bc_.set_outlet_pressure(patches_[k], p_next);
  }
  bc_.impose_pressure(pressure);
}

}  // namespace valsalva::flow
