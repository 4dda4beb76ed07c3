// Lumped-parameter (0D) outlets coupled implicitly to the projection:
//   resistance_outlet  P = p0 + R Q
//   rcr_outlet         P = p_d + R_p Q,  C dp_d/dt = Q - p_d / R_d  (three-element Windkessel)
// with Q the patch's outward flux and P its (uniform) pressure, a Dirichlet value of the Poisson
// equation for dp.
//
// Coupling (why implicit): an explicit coupling P^{n+1} = law(Q^n) is unstable once R times the
// 3D domain's flux response to its outlet pressure exceeds 1 per step (small C, large R, several
// outlets; Vignon-Clementel, Figueroa, Jansen & Taylor, Comput. Methods Appl. Mech. Engrg. 195,
// 3776-3796, 2006, who couple resistance and RCR implicitly in the weak form). Here, as in the
// modular implicit 0D/3D coupling of Esmaily Moghadam, Vignon-Clementel, Figliola & Marsden,
// J. Comput. Phys. 244, 63-79, 2013, the 3D side's response is computed and the lumped law
// solved together with it, in the Dirichlet-pressure form of our projection:
//   dp = dp_0 + sum_k delta_k phi_k,   lap(phi_k) = 0, phi_k = 1 on the nodes of outlet k and 0
//   on every other Dirichlet node (one Poisson solve per lumped outlet, once per run),
// dp_0 the usual solve with the previous increments as Dirichlet values. The velocity, the face
// flux and the mass correction are linear in dp, so the end-of-step fluxes are exactly
//   Q = Q_0 + M delta,  M_jk = -(dt/rho) flux_j(impose-linear(grad phi_k))
// (BoundaryConditions::flux_response), and the law P_j^{n+1} = a_j + b_j Q_j^{n+1} (affine for
// both outlets) gives (I - diag(b) M) delta = a + diag(b) Q_0 - P^n - dp_0|outlet, a small dense
// system solved alike on every rank. The law then holds at the end of every step to round-off,
// whatever R and C. With a single Dirichlet patch phi = 1, M = 0: the outlet pressure shifts the
// whole pressure field and Q is the inflow (incompressibility).
//
// Time integration of p_d (why this one): the pressure is a step-level unknown of the projection
// (every RK stage sees p^n, flow/projection_rk4.hpp), so the lumped state advances once per step,
// from t^n to t^{n+1}, by the exact solution of the linear ODE for Q linear in time between Q^n
// and Q^{n+1} (an exponential integrator):
//   p_d^{n+1} = e^{-h} p_d^n + R_d [w_0 Q^n + w_1 Q^{n+1}],  h = dt / (R_d C),
//   w_0 = (1 - e^{-h}) / h - e^{-h},  w_1 = 1 - (1 - e^{-h}) / h.
// 2nd order like the trapezoidal rule (w_0, w_1 -> h/2 for small h), but exact for any tau =
// R_d C: no step-size limit and no trapezoidal ringing (its factor -> -1) when C is small.
//
// Inlets held the same way:
//   pressure_inlet   P^{n+1} = p_in(t^{n+1}): offset only (slope 0);
//   elastance_inlet  P = E(t) (V - V0), V^{n+1} = V^n + dt (Q^n + Q^{n+1}) / 2 + D (trapezoidal,
//                    exact for Q linear in time like the p_d update), Q outward (dV/dt = -inflow);
//                    P^{n+1} = E(t^{n+1}) (V^{n+1} - V0) is affine in Q^{n+1}, slope E dt / 2.
//                    D = 0, or with venous_return the volume the named rcr_outlet's distal
//                    resistance passed over the step, D = dt (Q_r^n + Q_r^{n+1}) / 2 -
//                    C (p_d^{n+1} - p_d^n) (its own update above), affine in Q_r^{n+1}: the law
//                    gets a cross term and V + C p_d changes by dt/2 times the sum of the two
//                    patches' fluxes at t^n and t^{n+1}, zero to round-off in a closed pipe.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "flow/boundary_conditions.hpp"
#include "flow/face_flux.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

// One lumped outlet's state at t^n.
struct LumpedState {
  double flux = 0;       // Q^n, outward, m^3/s
  double pressure = 0;   // P^n, Pa
  double distal = 0;     // rcr: p_d^n, Pa; elastance_inlet: V^n, m^3 (others: 0)
  double increment = 0;  // P^n - P^{n-1}, Pa: the next solve's Dirichlet guess
};
inline constexpr int lumped_state_size = 4;

// The weights of the p_d update above for h = dt / tau.
struct DistalWeights {
  double decay = 1, w0 = 0, w1 = 0;
};
DistalWeights distal_weights(double h);

// P^{n+1} = offset + slope Q^{n+1} + cross Q_source^{n+1} over one step of length dt from
// `state` to t_next (source: the lumped index of a venous return, -1 = none).
struct OutletStep {
  double offset = 0, slope = 0;
  int source = -1;
  double cross = 0;
};
OutletStep outlet_step(const BoundarySpec& spec, const LumpedState& state, double dt,
                       double t_next = 0);
// rcr: p_d^{n+1} for the flux q_next at t^{n+1}; elastance_inlet: V^{n+1} without the venous
// return; others: 0.
double distal_after(const BoundarySpec& spec, const LumpedState& state, double q_next, double dt);
// The volume an rcr_outlet's distal resistance passes over one step, D = d0 + d1 Q^{n+1}.
struct VenousStep {
  double d0 = 0, d1 = 0;
};
VenousStep venous_step(const BoundarySpec& rcr, const LumpedState& state, double dt);
// The pressure at one instant t for flux q and state `distal` (a run's start).
double outlet_pressure(const BoundarySpec& spec, double q, double distal, double t = 0);
// The log column prefix of LumpedState::distal ("distal_pressure_", "volume_"), null = none.
const char* distal_column(BoundaryType type);

class LumpedOutlets {
 public:
  using Solve = std::function<void(const ScalarField& f, ScalarField& x)>;
  using Gradient = std::function<void(const ScalarField& p, VectorField& grad)>;
  // Collective. `solve`: lap(x) = f with the projection's Poisson matrix (Dirichlet values from
  // x on entry); `gradient`: the projection's pressure gradient. Computes phi_k, grad phi_k.
  LumpedOutlets(const mesh::LocalMesh& mesh, BoundaryConditions& bc, const Solve& solve,
                const Gradient& gradient);

  int count() const { return static_cast<int>(patches_.size()); }
  int patch(int i) const { return patches_[i]; }  // LocalMesh::patch_names index
  const BoundarySpec& spec(int i) const { return bc_.specs()[spec_[i]]; }
  const LumpedState& state(int i) const { return states_[i]; }

  // Collective. A new run: Q^0 from the (boundary-imposed) velocity, P^0 = p0 (resistance) or
  // p_d(0) = BoundarySpec::distal_pressure (RCR), the law at zero flux, written into the
  // pressure at the outlets' nodes; sum_k P_k^0 phi_k is added to the pressure elsewhere.
  // Inlets: p_in(t), E(t) (V(0) - V0).
  void start(const VectorField& velocity, ScalarField& pressure, double t = 0);
  // The states as lumped_state_size values per outlet (checkpoints) and back.
  std::vector<double> saved() const;
  void restore(const std::vector<double>& values);

  // Before the end-of-step Poisson solve: the previous increments as Dirichlet values of dp.
  void guess_increment(ScalarField& dp) const;
  // Collective. After that solve and its correction of u (v* - dt/rho grad dp_0) and of the face
  // flux: imposes the boundary conditions at t_next, solves for the outlet pressures and adds
  // delta_k phi_k to dp, -dt/rho delta_k grad phi_k to u, the compact gradient to the flux.
  void couple(VectorField& u, EdgeField& flux, ScalarField& dp, const std::vector<double>& weights,
              double dt, double dt_over_rho, double t_next);
  // Collective. After the step's final impose(): the new states from the end-of-step fluxes,
  // P^{n+1} = offset + slope Q^{n+1} written into the pressure at the outlets' nodes.
  void finish(const VectorField& velocity, ScalarField& pressure, double dt);
  // dQ/dP of the last step, M (m^3/(s Pa)): the explicit coupling's amplification is
  // diag(slope) M (studies).
  const Eigen::MatrixXd& response() const { return response_; }
  const std::vector<OutletStep>& steps() const { return steps_; }
  // max_j |P_j the projection used - P_j of the law at the end-of-step flux| of the last step,
  // Pa: zero to round-off when flux_response() predicts impose() exactly (tests).
  double last_mismatch() const { return mismatch_; }

 private:
  const mesh::LocalMesh& mesh_;
  BoundaryConditions& bc_;
  std::vector<int> patches_, spec_;
  std::vector<int> source_;  // per lumped patch: lumped index of its venous return, -1 = none
  std::vector<ScalarField> phi_;
  std::vector<VectorField> grad_phi_;
  std::vector<LumpedState> states_;
  std::vector<OutletStep> steps_;
  Eigen::MatrixXd response_, system_;
  Eigen::VectorXd rhs_, delta_;
  std::vector<double> used_;  // P^n + guess + delta of the last step
  double mismatch_ = 0;
};

}  // namespace valsalva::flow
