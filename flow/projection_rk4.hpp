// Incremental-pressure projection with an explicit 4-stage Runge-Kutta predictor (Chorin, Math.
// Comp. 22, 1968; stage form as in YALES2, Moureau, Domingo & Vervisch, C. R. Mécanique 339,
// 2011), with the scheme of flow/time_scheme.hpp (ProjectionOptions::time_scheme):
//   w_0 = v^n;  w_k = v^n + c_k dt [ R(w_{k-1}) - grad(p^n)/rho ],  k = 1..3,
//   v* = v^n + dt [ sum_k b_k R(w_k) - grad(p^n)/rho ],  R(w) = -div(w w) + nu lap(w) + f_b/rho;
//   lap(dp) = rho div(v*) / dt;   v^{n+1} = v* - dt grad(dp) / rho;   p^{n+1} = p^n + dp.
// rk4_jameson (the default: c = 1/4, 1/3, 1/2, v* = w_4 with coefficient 1) is 4th order in
// time for linear autonomous right-hand sides and 2nd order for the nonlinear momentum
// equation; rk4_classic is the classic 4th-order scheme. Either way only v* is projected: the
// stages w_1..w_3 carry the divergence that grad(p^n) leaves and see the old pressure. Measured
// (validation/time_order, 3D Taylor-Green Re 1600): every variant, with project_stages too, is
// 2nd order in time, rk4_classic with rk4_jameson's error; the limit is mainly the approximate
// projection (the nodal velocity is not discretely divergence-free), see docs/validation.md.
// ProjectionOptions::project_stages projects every stage velocity as well (Sanderse & Koren,
// J. Comput. Phys. 231, 3041-3063, 2012, the "projection at every stage" of their explicit RK
// methods for the index-2 DAE): w_k* as above, lap(dp_k) = rho div(w_k*) / (c_k dt), w_k =
// w_k* - c_k dt grad(dp_k) / rho, and the stage's convective flux is the projected face flux
// of w_k (plus P_c(w_k) - P_p(w_k), see below); three more Poisson solves per step, warm-started
// from c_k dp of the previous step (so a restart repeats the run bit for bit). dp_k only
// projects: the pressure gradient of every stage stays grad(p^n).
// Spatial operators: flow/operators.hpp (2nd-order centred),
// Poisson: flow/pressure_poisson.hpp. Boundary conditions (ProjectionOptions::boundary, see
// flow/boundary_conditions.hpp): imposed on every stage at t + c_k dt and again after the
// correction at t + dt; convective outlets advance with the stage form (with rk4_classic the
// last update uses the b-weighted stage velocities, the outlet equation being linear); dp is
// Neumann at velocity boundaries and Dirichlet (dp = 0) at pressure
// outlets (the caller puts BoundaryConditions::pressure_dirichlet() into poisson.dirichlet).
// Periodic patches carry no boundary faces. Lumped outlets (resistance, RCR) are Dirichlet
// patches whose pressure is solved with their flux at the end of each step
// (flow/lumped_outlets.hpp).
// Face flux (flow/face_flux.hpp): the projection also corrects the dual-face volume flux F with
// the Poisson matrix's own compact gradient, so that sum_k F_jk + B_j = 0 at every node to the
// Poisson tolerance; F is part of the state (face_flux(), saved in checkpoints). The convective
// term of stage i is the skew-symmetric form (flow/convection_scheme.hpp) carried by
//   F_i = P_c(w_{i-1}) + [F^n - P_p(v^n)],
// P_p the projection divergence's face value, P_c the scheme's ((u_j + u_k)/2 for central2,
// the Hermite value for central4): F^n at the first stage when P_c = P_p, following the stage
// velocity after it (the time order of the nodal flux is kept). The convective term is
// energy-neutral for any F; the projected F^n is what makes it consistent with div(u u).
// Mass balance: at walls and inlets the boundary flux B_j = u_j . A_j that the projection used
// is the one the next step sees (both are the imposed values); at outlets the corrected (held)
// velocity changes B_j after the projection, and Dirichlet (pressure-outlet) nodes are not
// balanced by the Poisson solve, so there F is not divergence-free: the convective term's
// energy contribution is still exactly the kinetic-energy flux sum_j B_j |u_j|^2 / 2.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "flow/boundary_conditions.hpp"
#include "flow/convection_scheme.hpp"
#include "flow/damping_cells.hpp"
#include "flow/lumped_outlets.hpp"
#include "flow/operators.hpp"
#include "flow/operators_order4.hpp"
#include "flow/pressure_poisson.hpp"
#include "flow/time_scheme.hpp"
#include "flow/viscosity_model.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

struct FlowState {
  VectorField velocity;  // m/s, owned + ghosts
  ScalarField pressure;  // Pa
  double time = 0;       // s
};

struct ProjectionOptions {
  double density = 1.0;                              // kg/m^3
  double viscosity = 0.0;                            // kinematic, m^2/s
  ConvectionKind scheme = ConvectionKind::central2;  // flow.scheme (flow/convection_scheme.hpp)
  // Laminar viscous term with the Poisson matrix's edge weights and no non-orthogonal
  // correction (flow::viscous with correction = false): on all-tetrahedral meshes with the P1
  // weights of flow::poisson_weights this is the median-dual flux of the piecewise-linear
  // velocity. false: two-point weights + correction with nodal gradients (flow::viscous).
  bool stiffness_viscous = false;
  // The pressure damping term of step() (with boundary conditions); false only for studies.
  bool pressure_damping = true;
  // The same damping also without boundary conditions (periodic boxes). It turns the
  // incremental projection into a non-incremental one (p^{n+1} = L^-1 div(v* + dt grad p^n /
  // rho) rho / dt), which removes pressure modes that the wide gradient hardly sees and that
  // otherwise decay over thousands of steps on irregular tetrahedra (validation/stability), at
  // the price of an O(h^2) pressure error (twice the Taylor-Green central2 error on hexahedra),
  // so it is off by default.
  bool periodic_pressure_damping = false;
  // poisson.damping = "increment": the damping acts on the last increment p^n - p^{n-1}, except
  // in the tetrahedra (edges) with a node on an open boundary (any patch but wall and slip),
  // where it keeps acting on p^n. The damping flux then vanishes in a steady state and is
  // O(dt^2) per step in a smooth flow: no flux through a loaded immersed wall (the closed valve's
  // leak) and an energy loss that falls with dt. With the increment at a convective outlet too,
  // its odd-even pressure mode grew until the run diverged (valve_quick, t = 0.078 s).
  // Tetrahedral meshes need set_damping_cells (whole tetrahedra keep the damping PSD).
  bool damp_pressure_increment = false;
  // 4th-order laminar viscous term, pressure gradient and divergence (flow/operators_order4.hpp;
  // the viscous term with the Poisson matrix's edge weights): with central4, a 4th-order
  // velocity on uniform hexahedra and split tetrahedra (validation/taylor_green). The Poisson
  // matrix, the pressure damping term and the subgrid part of an LES viscous term (the
  // full-stress operator with nu_sgs) stay 2nd order; refused with a non-Newtonian fluid. Needs
  // 2 ghost layers.
  bool fourth_order_operators = false;
  PoissonOptions poisson;
  TimeScheme time_scheme = TimeScheme::rk4_jameson;  // time.scheme (flow/time_scheme.hpp)
  bool project_stages = false;  // time.project_stages: project w_1..w_3 too (see above)
  // LES: fills nu_sgs [m^2/s] at owned and ghost nodes from the velocity gradient of RK stage
  // `stage` = 0..3 (owned + ghosts valid; nu_sgs is sized by the solver and holds the values of
  // the previous call, so a hook may leave it unchanged at stages 1-3 to freeze nu_sgs over the
  // step, les::SgsUpdate). Empty = laminar: the constant-nu Laplacian runs and nothing else is
  // computed or allocated. When set, the viscous term is the full stress
  // div((nu + nu_sgs)(grad u + grad u^T)) (flow/viscous_stress.hpp).
  std::function<void(int stage, const TensorField& grad_u, ScalarField& nu_sgs)> subgrid_viscosity;
  // Non-Newtonian fluid (law != newtonian): `viscosity` is not used; the kinematic viscosity of
  // every node is mu(gamma_dot) / density from the gradient of the RK stage's own velocity, so
  // the right-hand side of each stage is a function of that stage alone (a viscosity frozen over
  // the step would make the viscous term 1st order in time), and the viscous term is the full
  // stress div((nu(gamma_dot) + nu_sgs)(grad u + grad u^T)) (flow/viscous_stress.hpp).
  ViscosityModel rheology;
  std::shared_ptr<BoundaryConditions> boundary;  // null: every patch periodic
};

struct StepReport {
  PoissonResult poisson;             // the end-of-step projection
  int stage_poisson_iterations = 0;  // summed over the stage projections (project_stages)
  double max_divergence = 0;         // max |div v^{n+1}| over owned nodes, 1/s
  // max |div v^{n+1}| h / max |v^{n+1}| with h = (dual volume)^(1/3) per node: the projection's
  // divergence error as a fraction of the resolved velocity gradient, comparable between meshes
  // with graded cells (0 when the flow is at rest).
  double divergence_number = 0;
  Eigen::Vector3d divergence_position = Eigen::Vector3d::Zero();  // m: the node of that maximum
  // The same over the nodes whose velocity the projection corrects, i.e. without the wall and
  // inflow nodes whose velocity impose() sets (equal to the above without boundary conditions).
  double free_divergence_number = 0;
  Eigen::Vector3d free_divergence_position = Eigen::Vector3d::Zero();
};

// Body-force density f [N/m^3] at owned and ghost nodes (overwritten), evaluated once per RK
// stage from that stage's velocity; f/rho enters the momentum right-hand side. Stage k = 0..3
// uses the velocity w_k at stage_time = t^n + c_k dt (flow/time_scheme.hpp: c = 0, 1/4, 1/3,
// 1/2 for rk4_jameson, 0, 1/2, 1/2, 1 for rk4_classic).
using BodyForce = std::function<void(
    int stage, double stage_time, const VectorField& stage_velocity, VectorField& force_density)>;

class ProjectionRK4 {
 public:
  // `poisson_weights`: edge weights of the Poisson matrix (flow::poisson_weights); empty means
  // the two-point weights of flow::laplacian_weights (consistent on uniform hexahedra only).
  ProjectionRK4(const mesh::LocalMesh& mesh, ProjectionOptions options,
                std::vector<double> poisson_weights = {});

  // Advances `state` by dt; ghosts of the state are valid on return. The face flux of the last
  // step is used when state.velocity is still the velocity it belongs to; otherwise (a new or
  // modified state) it starts from the face value of the nodal velocity.
  StepReport step(FlowState& state, double dt);

  // The projection of step() on its own (no pressure damping, dt / rho = 1): solves
  // lap(q) = div(u) with the face flux of u, corrects u -= grad q and the face flux by the
  // compact gradient of q, and keeps that flux as the state's for `u` (velocity boundary
  // conditions are not imposed). `q` is the warm start on entry, the solution on return.
  PoissonResult project(VectorField& u, ScalarField& q);

  // The face flux of the state (one value per local edge, LocalMesh::edges orientation) and the
  // velocity it belongs to: restarts set both (a checkpoint stores the flux by global edge).
  const EdgeField& face_flux() const { return flux_; }
  void set_face_flux(const EdgeField& flux, const VectorField& velocity);
  // The flux the convective term of a step's first stage uses for `u`: face_flux() when u is
  // the velocity it belongs to, else the face value of u.
  const EdgeField& convective_flux(const VectorField& u);

  // Momentum right-hand side without the pressure gradient: -div(u u) + nu lap(u) with the
  // convective term carried by `flux` (one value per local edge); `stage` is handed to the
  // subgrid hook.
  void momentum_rhs(const VectorField& u, const EdgeField& flux, VectorField& rhs, int stage = 0);
  // The same with the flux of a step's first stage for u (convective_flux(u)).
  void momentum_rhs(const VectorField& u, VectorField& rhs, int stage = 0);

  const std::vector<double>& laplacian_weights() const { return weights_; }
  // The edge weights of the laminar viscous term and whether it has the non-orthogonal
  // correction (see ProjectionOptions::stiffness_viscous): what flow::wall_force needs.
  const std::vector<double>& viscous_weights() const {
    return options_.stiffness_viscous || order4_ ? poisson_weights_ : weights_;
  }
  bool viscous_correction() const { return !options_.stiffness_viscous && !order4_; }

  // The last pressure increment dp (the warm start of the next Poisson solve): saved in
  // checkpoints so that a restarted run repeats the uninterrupted one bit for bit.
  const ScalarField& pressure_increment() const { return dp_; }
  void set_pressure_increment(const ScalarField& dp);

  // nu_sgs of the last RK stage evaluated (owned + ghosts; empty without a subgrid model).
  const ScalarField& subgrid_viscosity() const { return nu_sgs_; }
  // Restores that nu_sgs (all local nodes) from a checkpoint: the first time step of a restarted
  // LES then sees the same nu + max nu_sgs as the uninterrupted run. Throws on a wrong size or
  // without a subgrid model.
  void set_subgrid_viscosity(const ScalarField& nu_sgs);
  // Collective: max over owned nodes of that nu_sgs (0 without a subgrid model), m^2/s.
  double max_subgrid_viscosity() const;
  // A non-Newtonian fluid (ProjectionOptions::rheology)?
  bool variable_viscosity() const { return rheology_; }
  // With one: the kinematic viscosity nu(gamma_dot(u)) + nu_sgs of the velocity u at every local
  // node (nu_sgs of the last stage evaluated), m^2/s, what the time step's viscous (Fourier)
  // bound uses node by node. Computed from u alone, so a restart sees the same values.
  const ScalarField& viscosity_field(const VectorField& u);

  // Installs (or, with an empty function, removes) the body-force hook; without one no force
  // array is allocated or touched.
  void set_body_force(BodyForce force) { body_force_ = std::move(force); }
  // Nodes (local, owned + ghosts, the same value on every rank that holds them) near which
  // step() keeps only the fraction `kept` (0..1) of its pressure damping term: the kernel
  // support of immersed markers. Across the
  // pressure jump an immersed force holds, the damping term dt/rho (avg(grad p) - grad p|_face)
  // is large and it is a face flux through the structure: a leak proportional to dt
  // (docs/valve.md, "The pressure damping and the immersed jump"). Empty = damping everywhere.
  // Throws when `nodes` is neither empty nor one value per local node. On all-tetrahedral
  // meshes with P1 Poisson weights give the damping's element shares (set_damping_cells): the
  // term is then left out of every tetrahedron with an undamped node. Without them it is left
  // out of every edge with an undamped node, which is stable only where all Poisson weights are
  // non-negative (the two-point weights of other meshes; damping_cells.hpp). Tetrahedra and
  // edges with a boundary node keep the fraction `kept_at_boundary` instead (default: all).
  void set_undamped_nodes(const std::vector<char>& nodes, double kept = 0.0,
                          double kept_at_boundary = 1.0);
  void set_damping_cells(std::shared_ptr<const DampingCells> cells) { cells_ = std::move(cells); }

  // The lumped outlets of the boundary conditions (null without any): their states for the
  // log and checkpoints; a new run calls start(), a restart restore().
  LumpedOutlets* lumped_outlets() { return lumped_.get(); }
  const LumpedOutlets* lumped_outlets() const { return lumped_.get(); }

 private:
  const mesh::LocalMesh& mesh_;
  ProjectionOptions options_;
  std::vector<double> weights_, poisson_weights_;
  std::unique_ptr<ConvectionScheme> convection_;
  // central4 without the 4th-order operators: the flux form apply(u, conv), not energy-neutral
  // (the skew form is not yet validated on that, the LES, path).
  bool old_convection_ = false;
  std::unique_ptr<Order4Operators> order4_;  // only with options.fourth_order_operators
  PressurePoisson poisson_;
  ScalarField dp_, div_;  // dp_ is kept between steps: warm start of the next solve
  // The pressure gradient and the divergence of the projection: 2nd or 4th order.
  void pressure_gradient(const ScalarField& p, VectorField& grad);
  void projection_divergence(const VectorField& u, ScalarField& div);
  // F = P_p(u) (projection_flux) or P_c(u) (scheme_flux) on every local edge.
  void projection_flux(const VectorField& u, EdgeField& flux);
  void scheme_flux(const VectorField& u, EdgeField& flux);
  // Solves lap(dp) = (rho/dt) div(F) (with the boundary flux of u) and corrects u and F; dp is
  // the warm start on entry.
  PoissonResult correct(VectorField& u, EdgeField& flux, double dt_over_rho, ScalarField& dp);
  // F = P_p(w) plus the pressure damping term of a predictor over `dt` with the old pressure
  // p (when there are boundary conditions or periodic_pressure_damping): the flux to project.
  void predicted_flux(const VectorField& w, double dt, const ScalarField& p, EdgeField& flux);
  // The damping term over `dt` of pressure p with gradient grad_p, added to flux.
  void add_damping(double dt, const VectorField& grad_p, const ScalarField& p, EdgeField& flux);
  // damp_pressure_increment: takes the damping of previous_p_ back out away from open
  // boundaries.
  void remove_previous_pressure_damping(double dt, EdgeField& flux);
  void mark_boundary_nodes();  // fills on_boundary_ and open_boundary_ (once)
  // project_stages: projects stage velocity w (standing at t = t^n + c dt) and leaves its
  // convective face flux in stage_flux_; returns the Poisson iterations.
  int project_stage(VectorField& w, double c, double dt, double t, const ScalarField& p);
  // max |div_[i]| h_i over owned nodes with skip[i] == 0 (skip empty: all), divided by
  // max_speed, and where it is (collective; the lowest rank on a tie).
  std::pair<double, Eigen::Vector3d> divergence_peak(const std::vector<char>& skip,
                                                     double max_speed) const;
  std::vector<char> velocity_held_;  // BoundaryConditions::velocity_dirichlet() of the step
  RungeKuttaTableau rk_;
  EdgeField flux_, stage_flux_, flux_offset_;
  VectorField flux_velocity_;  // the velocity flux_ belongs to (empty: none)
  TensorField grad_flux_;      // velocity gradient of the Hermite face value
  VectorField grad_p_, grad_dp_, rhs_, conv_, stage_;
  ScalarField previous_p_;           // damp_pressure_increment: p^n - theta dp_ (step())
  VectorField grad_previous_p_;      // its wide gradient
  std::vector<char> every_node_;     // all local nodes marked (DampingCells::remove)
  VectorField subgrid_rhs_;          // the subgrid viscous term with the 4th-order operators
  VectorField rhs_sum_, stage_sum_;  // rk4_classic: sum b_k R(w_k); sum b_k w_k (outlets)
  ScalarField stage_dp_;             // project_stages: dp of the current stage
  TensorField grad_u_;
  // grad_u_ = gradient(mesh_, u), or taken from grad_flux_ when stage_gradient_known_ (set by
  // step() for the one momentum_rhs call that follows central4's face flux of the same stage).
  void velocity_gradient(const VectorField& u);
  bool stage_gradient_known_ = false;
  ScalarField nu_sgs_, nu_eff_;  // LES or non-Newtonian: subgrid and total viscosity
  bool rheology_ = false;        // options_.rheology is not Newtonian
  // nu_eff_ = nu(gamma_dot(grad_u_)) (or the constant nu) + nu_sgs_ at every local node.
  void total_viscosity();
  BodyForce body_force_;
  std::vector<char> undamped_;  // set_undamped_nodes
  double kept_damping_ = 0.0, kept_damping_at_boundary_ = 1.0;
  std::vector<char> on_boundary_;    // nodes with a boundary face (mark_boundary_nodes)
  std::vector<char> open_boundary_;  // nodes with a face on a patch that is not a wall or slip
  std::shared_ptr<const DampingCells> cells_;
  EdgeField damping_flux_;  // predicted_flux's damping term when some nodes are undamped
  VectorField force_;       // body-force density of the current stage (only with a hook)
  std::unique_ptr<LumpedOutlets> lumped_;
};

}  // namespace valsalva::flow
