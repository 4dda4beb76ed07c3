// The immersed thick boundary method (ITBM) coupling: solids whose nodes are markers in the
// fluid (Peskin, Acta Numerica 11, 2002; thick membranes on unstructured meshes with RKPM
// kernels: Sigüenza, Mendez, Nicoud et al., Int. J. Numer. Meth. Biomed. Engng. 32, 2016).
// Solid inertia is neglected (the fluid fills the solid); each marker moves with the fluid:
//   dX/dt = U(X) = sum_j u_j phi(x_j, X) V_j,     f_j = sum_a F_a(X) phi(x_j, X_a).
//
// Time integration is the flow's RK4 (flow/time_scheme.hpp, ImmersedOptions::time_scheme: the
// scene's time.scheme) applied to the pair (u, X), through the ProjectionRK4 body-force hook
// (mode per_stage):
//   stage k = 0..3 at t_k = t^n + c_k dt (c = 0, 1/4, 1/3, 1/2 for rk4_jameson; 0, 1/2, 1/2, 1
//   for rk4_classic):
//     X_k = X^n + c_k dt U_{k-1}          (X_0 = X^n)
//     F_k = F(X_k) (internal + tether), spread to the fluid force density
//     U_k = interpolation of the stage velocity u_k at X_k
//   after the projection: X^{n+1} = X^n + dt sum_k b_k U_k (b = 0, 0, 0, 1 for rk4_jameson,
//   i.e. X^n + dt U_3; 1/6, 1/3, 1/3, 1/6 for rk4_classic).
// Mode per_step (classic explicit IB): F(X^n) spread once and held over the four stages;
// X^{n+1} = X^n + dt U(u^{n+1}, X^n) with the projected, divergence-free velocity.
// Mode implicit: F(X^n) - K dX^{n-1} held over the four stages, then the markers' displacement
// from the linearly implicit solve of ibm/implicit_markers.hpp with the velocity u^{n+1} at X^n;
// no time-step bound of its own (the flow's CFL and Fourier targets set dt).
// Which to use and why: see ibm/ib_stability.hpp and the membrane_relaxation case.
//
// Parallel: markers and solid forces are replicated on every rank (solids have thousands of
// nodes); ibm::DiracTransfer evaluates each marker on one rank and halo-exchanges.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "flow/projection_rk4.hpp"
#include "flow/time_scheme.hpp"
#include "ibm/dirac_transfer.hpp"
#include "ibm/immersed_body.hpp"
#include "ibm/implicit_markers.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::ibm {

enum class CouplingMode { per_stage, per_step, implicit };

// Mode implicit: what the marker solve of a step adds to the flow step (ibm/implicit_markers.hpp).
//   lagged:         (I + c A K) dX = dt U*               (the fluid felt -K dX^{n-1}; the solve
//                                                        adds -c A K dX on top of it)
//   consistent:     (I + c A K) dX = dt U* + c A K dX^{n-1}  (only the correction beyond what
//                                                        the flow felt; the fluid keeps its lag)
//   backward_euler: (I + c A_P K) dX = dt U* + c A_P K dX^{n-1}, A_P = Interp P Spread (one
//                   pressure projection per product), then the fluid velocity is corrected by
//                   (dt/rho) P Spread(-K (dX - dX^{n-1})) and the pressure by that projection's
//                   potential (rho/dt q): the linearised backward-Euler step of Newren, Fogelson,
//                   Guy & Kirby (2007), markers moving with the corrected fluid.
// c = dt^2/rho, A = Interp Spread at X^n. Measured limits and why lagged stays the default:
// ibm/implicit_markers.hpp. backward_euler is not a scene key yet: the run loop's finish_step
// hands the coupling a const state and no projector (run/immersed_run.cpp).
enum class ImplicitVariant { lagged, consistent, backward_euler };

inline const char* implicit_variant_name(ImplicitVariant v) {
  switch (v) {
    case ImplicitVariant::consistent:
      return "consistent";
    case ImplicitVariant::backward_euler:
      return "backward_euler";
    default:
      return "lagged";
  }
}

// The scene's name of a mode (immersed.coupling).
inline const char* coupling_name(CouplingMode mode) {
  switch (mode) {
    case CouplingMode::per_step:
      return "per_step";
    case CouplingMode::implicit:
      return "implicit";
    default:
      return "per_stage";
  }
}

// A periodic fluid box: markers are wrapped into it for location (the solid keeps unwrapped
// positions for its forces).
struct PeriodicBox {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d length = Eigen::Vector3d::Ones();
  std::array<bool, 3> periodic{false, false, false};
};

// x moved by whole periods into [origin, origin + length) along the periodic directions.
inline Eigen::Vector3d wrap_into(const PeriodicBox& box, Eigen::Vector3d x) {
  for (int d = 0; d < 3; ++d)
    if (box.periodic[d]) x[d] -= box.length[d] * std::floor((x[d] - box.origin[d]) / box.length[d]);
  return x;
}

struct ImmersedOptions {
  TransferOptions transfer;
  CouplingMode mode = CouplingMode::per_stage;
  // The flow's time scheme (ProjectionOptions::time_scheme): its stage weights move the markers.
  flow::TimeScheme time_scheme = flow::TimeScheme::rk4_jameson;
  double fluid_density = 1.0;      // kg/m^3, for the stability bound
  std::optional<PeriodicBox> box;  // wrap markers across periodic directions
  double stability_safety = 1.0;   // dt is refused above safety * dt_max (ib_stability.hpp)
  // Mode implicit: the marker solve (ImplicitVariant above); backward_euler needs set_projector
  // and the mutable finish_step.
  ImplicitVariant implicit_variant = ImplicitVariant::lagged;
  // Mode implicit, variant lagged: Newton iterations on the force, at most this many (1: the
  // linearisation at X^n alone), until the update is below `implicit_newton_tolerance` times the
  // displacement (implicit_markers.hpp).
  int implicit_newton_iterations = 1;
  double implicit_newton_tolerance = 1e-6;
};

class ImmersedStructure {
 public:
  // The fluid mesh must outlive this object.
  ImmersedStructure(mesh::LocalMesh& mesh, ImmersedOptions options);

  // Adds a solid (before the first step); returns its index. Its markers start at the mesh's
  // reference positions.
  int add_body(const structure::SolidMesh& mesh, const structure::Material& material,
               BodySpec spec);

  // Moves all markers (3 x num_markers(), e.g. a pre-deformed initial shape or a restart).
  void set_positions(const Eigen::Matrix3Xd& x);

  // The hook for flow::ProjectionRK4::set_body_force (captures `this`).
  flow::BodyForce body_force();
  // Stage k of the step from stage_time: positions X_k, forces, spread into `force_density`
  // (owned + ghosts, overwritten), interpolation of `stage_velocity`. Collective.
  void stage_force(int stage, double stage_time, const flow::VectorField& stage_velocity,
                   flow::VectorField& force_density);
  // After ProjectionRK4::step: markers to X^{n+1} (state.time is t^{n+1}). Collective.
  // ImplicitVariant::backward_euler corrects state.velocity and needs the second form.
  void finish_step(const flow::FlowState& state);
  void finish_step(flow::FlowState& state);
  // The flow's pressure projection of a nodal field in place (flow::ProjectionRK4::project),
  // for ImplicitVariant::backward_euler.
  void set_projector(Projector project) { projector_ = std::move(project); }

  // The force density the markers spread at their current positions (owned + ghosts,
  // overwritten), with the forces evaluated there: for output between steps (the next step
  // locates its own stages again). Collective.
  void current_force_density(flow::VectorField& density);
  // 1 on every local node (owned + ghosts) in the kernel support of a coupled marker at its
  // current position, else 0, the same on every rank that holds the node. Collective.
  void support_nodes(std::vector<char>& nodes);

  // Largest stable time step of the explicit coupling at the current positions, from the
  // largest eigenvalue of the kernel-mapped stiffness (ib_stability.hpp). Collective.
  double stable_time_step();
  // Throws, with the bound and where it comes from, when dt > safety * the last
  // stable_time_step() (computed now if it never was). Collective.
  void check_time_step(double dt);

  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  const ImmersedBody& body(int b) const { return *bodies_[b]; }
  int first_marker(int b) const { return first_[b]; }
  // All solid nodes (markers and fixed nodes); the coupled ones are the transfer's markers.
  int num_markers() const { return static_cast<int>(x_.cols()); }
  int num_coupled_markers() const { return static_cast<int>(coupled_.size()); }
  // Current positions, last marker velocities (after a step: the velocity that moved them) and
  // last forces (3 x markers, all bodies).
  const Eigen::Matrix3Xd& positions() const { return x_; }
  const Eigen::Matrix3Xd& velocities() const { return velocity_; }
  const Eigen::Matrix3Xd& forces() const { return force_; }
  // Positions, velocities and forces of body b only.
  Eigen::Matrix3Xd body_positions(int b) const { return x_.middleCols(first_[b], count(b)); }
  // Total force the body applies to the fluid (= its tether reaction: internal forces sum to
  // zero), and the tether reaction alone, at the last forces. With fixed clamped nodes
  // (Clamp::fixed) only the coupled markers act on the fluid and the "tether" reaction is the
  // support's: minus the forces at the fixed nodes.
  Eigen::Vector3d total_force(int b) const;
  Eigen::Vector3d tether_force(int b) const;
  double last_min_det() const { return min_det_; }
  // Mode implicit: the last step's marker displacement (3 x markers; part of the state, saved in
  // checkpoints so that a restart repeats the run) and its solve's BiCGSTAB iterations.
  const Eigen::Matrix3Xd& last_displacement() const { return last_displacement_; }
  void set_last_displacement(const Eigen::Matrix3Xd& d);
  int last_implicit_iterations() const { return implicit_iterations_; }
  // Mode implicit: Newton iterations of the last step's marker solve (1 without Newton).
  int last_newton_iterations() const { return newton_iterations_; }
  const DiracTransfer& transfer() const { return transfer_; }
  // Where each coupled marker's kernel support was last built (transfer.reuse_distance keeps it
  // while the marker stays near): part of the state, saved in checkpoints so that a restart
  // spreads and interpolates with the same weights. restore_location rebuilds the supports
  // there (collective; throws on a count that is not num_coupled_markers()).
  const std::vector<Eigen::Vector3d>& located_at() const { return transfer_.located_at(); }
  void restore_location(const std::vector<Eigen::Vector3d>& located_at);
  const ImmersedOptions& options() const { return options_; }

 private:
  int count(int b) const { return bodies_[b]->num_nodes(); }
  void gather(const Eigen::Matrix3Xd& all, Eigen::Matrix3Xd& coupled) const;
  Eigen::Vector3d fixed_force(int b) const;
  void compute_forces(const Eigen::Matrix3Xd& x);  // force_ at x, checks det F
  void locate(const Eigen::Matrix3Xd& x);          // wraps into the box
  void interpolate(const flow::VectorField& u);    // velocity_ at the located markers
  void spread(flow::VectorField& density);
  // K = -dF/dX of every body at x (into stiffness_) and its product with a vector of the coupled
  // markers (fixed nodes are Dirichlet: their rows and columns drop out).
  void assemble_stiffness(const Eigen::Matrix3Xd& x);
  void apply_coupled_stiffness(const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& kv);
  // finish_step; `correctable` (null from the const form) is the state backward_euler corrects.
  void finish(const flow::FlowState& state, flow::FlowState* correctable);
  void implicit_finish(double dt, flow::FlowState* state);
  // Newton iterations after the first lagged solve (ImmersedOptions::implicit_newton_iterations).
  void newton_lagged(const Eigen::Matrix3Xd& b, double c, ImplicitSolve& solve);
  // b + c A [F(X^n + d) - F(X^n)] - d on the coupled markers (throws on an inverted element).
  Eigen::Matrix3Xd lagged_residual(const Eigen::Matrix3Xd& b, double c, const Eigen::Matrix3Xd& d);
  // out = Interp (P) Spread v on the coupled markers (P with `projected`). Collective.
  void coupled_response(const Eigen::Matrix3Xd& v, Eigen::Matrix3Xd& out, bool projected);

  mesh::LocalMesh& mesh_;
  ImmersedOptions options_;
  DiracTransfer transfer_;
  std::vector<std::unique_ptr<ImmersedBody>> bodies_;
  std::vector<int> first_;
  Eigen::Matrix3Xd x_, x_n_, x_stage_, velocity_, force_;
  flow::RungeKuttaTableau rk_;
  Eigen::Matrix3Xd velocity_sum_;  // sum b_k U_k over the stages so far (rk4_classic only)
  std::vector<int> coupled_;       // markers of the coupling: every node but the fixed ones
  Eigen::Matrix3Xd wrapped_, coupled_force_, coupled_velocity_;  // per coupled marker
  double t_n_ = 0;
  double min_det_ = 1;
  double dt_max_ = -1;  // last stable_time_step(), -1 before the first
  flow::VectorField u_copy_, held_force_;
  std::vector<Eigen::SparseMatrix<double>> stiffness_;  // per body, at the last assembly
  Eigen::Matrix3Xd stiffness_in_, stiffness_out_;       // all markers, scratch
  Eigen::Matrix3Xd last_displacement_;                  // mode implicit: dX^{n-1}
  int implicit_iterations_ = 0;
  int newton_iterations_ = 0;
  Eigen::Matrix3Xd force_n_;  // mode implicit: F(X^n), before the extrapolation
  Projector projector_;
  flow::VectorField response_density_;
  flow::ScalarField response_potential_;
};

}  // namespace valsalva::ibm
