// Boundary conditions of the flow solver, one per non-periodic boundary patch (by name):
//   wall               u = u_wall (no-slip; a moving lid has a nonzero u_wall)
//   slip               u . n = 0 at the patch's nodes, n the node's area-weighted normal of the
//                      patch (several slip patches at a node: all their normals are removed)
//   inlet              u = profile(x, t) n_in, n_in the inward patch normal; profile flat,
//                      Poiseuille or Womersley (circular section: centre = area-weighted centroid,
//                      radius = the largest distance of a patch node from it), scaled by an
//                      additive multiple of its base shape so that the discrete flux
//                      -sum_j u_j . A_j equals Q(t) to round-off
//   convective_outlet  du/dt + U_c du/dn = 0, U_c = inflow / outflow area unless given
//   pressure_outlet    p = p_out (Dirichlet rows dp = 0 in the Poisson matrix); u from the
//                      momentum equation (free), with backflow stabilisation where u . n < 0
//                      (stabilize_backflow)
//   resistance_outlet  p = p0 + R Q, Q the patch's outward flux (a lumped outlet)
//   rcr_outlet         three-element Windkessel p = p_d + R_p Q, C dp_d/dt = Q - p_d / R_d
//                      (a lumped outlet). Lumped outlets are pressure outlets whose uniform
//                      pressure is coupled implicitly to their flux at the end of each step
//                      (flow/lumped_outlets.hpp); set_outlet_pressure() holds their value.
//   pressure_inlet     p = p_in(t) (a waveform), otherwise a pressure outlet: u free, with the
//                      same inflow stabilisation, which here acts on the whole patch
//   elastance_inlet    a lumped ventricle p = E(t) (V - V0), dV/dt = Q (+ the venous return
//                      of an rcr_outlet's distal flow), Q the outward patch flux.
//                      Both are lumped like the outlets above (a law affine in Q^{n+1}).
// Role exchange (pulse-duplicator inflow, see ../shared/design/architecture.md): an inlet with a
// partner (swap_with, a convective outlet) imposes Q(t) while Q >= 0; while Q < 0 the partner
// imposes |Q| inward with a flat profile and the inlet becomes a convective outlet.
// Global mass: after the conditions are imposed, the velocity of the free outflow nodes (outlet
// nodes not held by a wall, inlet or slip condition) is corrected along their outlet area
// vector a_j by u_j += c a_j, c = -(sum of all boundary fluxes) / sum |a_j|^2, so that the net
// boundary flux (the global mass imbalance, sum_j V_j div u_j) is zero to round-off.
// A node on several patches takes the strongest condition: stationary wall > moving wall >
// inflow > slip > outflow.
//
// How the conditions enter the projection + RK4 step (flow/projection_rk4.hpp):
//   stage i (time t + alpha_i dt): interior nodes from the momentum equation; convective-outlet
//   nodes w_i = u^n - alpha_i dt U_c (grad w_{i-1}) n; then impose() at t + alpha_i dt.
//   Poisson: Neumann (no boundary flux) for dp at every velocity boundary, Dirichlet dp = 0 at
//   pressure outlets; v* is mass-corrected first so that the singular all-Neumann problem is
//   consistent. After the correction v = v* - dt grad(dp)/rho, impose() at t + dt again: the
//   Dirichlet values are restored, convective-outlet nodes keep their predicted value.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flow/elastance.hpp"
#include "flow/inflow_waveform.hpp"
#include "flow/operators.hpp"
#include "flow/womersley.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

enum class BoundaryType {
  wall,
  slip,
  inlet,
  convective_outlet,
  pressure_outlet,
  resistance_outlet,
  rcr_outlet,
  pressure_inlet,
  elastance_inlet
};
// Patches whose uniform pressure follows a law of their flux and time, held by LumpedOutlets.
inline bool lumped_type(BoundaryType t) {
  return t == BoundaryType::resistance_outlet || t == BoundaryType::rcr_outlet ||
         t == BoundaryType::pressure_inlet || t == BoundaryType::elastance_inlet;
}
// Patches whose pressure is a Dirichlet value of the Poisson equation: fixed or lumped.
inline bool pressure_type(BoundaryType t) {
  return t == BoundaryType::pressure_outlet || lumped_type(t);
}
enum class InletProfile { flat, poiseuille, womersley, plane_poiseuille };

inline constexpr const char* boundary_type_names =
    "wall, slip, inlet, convective_outlet, pressure_outlet, resistance_outlet, rcr_outlet, "
    "pressure_inlet, elastance_inlet";

struct BoundarySpec {
  std::string patch;
  BoundaryType type = BoundaryType::wall;
  Eigen::Vector3d wall_velocity = Eigen::Vector3d::Zero();  // wall, m/s
  InletProfile profile = InletProfile::flat;                // inlet
  Waveform flow_rate;                                       // inlet, m^3/s
  std::string swap_with;                                    // inlet: partner convective outlet
  // plane_poiseuille: unit vector across the channel (between its two walls); the profile is
  // 6 (Q/A) s (1 - s), s in [0, 1] the patch position along it (a slab or 2D channel inlet).
  Eigen::Vector3d across = Eigen::Vector3d::Zero();
  // inlet: impose the profile's nodal values as they are, without scaling the discrete flux to
  // Q(t) (studies: the nodal interpolant of an exact solution as Dirichlet data).
  bool unscaled_profile = false;
  double pressure = 0;  // pressure_outlet: p_out; resistance_outlet: p0, Pa
  // resistance_outlet: R; rcr_outlet: the proximal R_p, Pa s/m^3
  double resistance = 0;
  double distal_resistance = 0;  // rcr_outlet: R_d, Pa s/m^3
  double capacitance = 0;        // rcr_outlet: C, m^3/Pa
  double distal_pressure = 0;    // rcr_outlet: p_d at the start of a run, Pa
  double convection_speed = 0;   // convective_outlet, m/s; 0 = inflow / outflow area
  Waveform inlet_pressure;       // pressure_inlet: p_in(t), Pa
  Elastance elastance;           // elastance_inlet: E(t), Pa/m^3
  double volume = 0;             // elastance_inlet: V at the start of a run, m^3
  double rest_volume = 0;        // elastance_inlet: V0, m^3
  std::string venous_return;     // elastance_inlet: rcr_outlet whose p_d / R_d fills V ("" none)
};

// A condition of `type` on `patch` with every other setting at its default (for code that
// builds conditions directly: validation cases, tests).
inline BoundarySpec boundary_spec(std::string patch, BoundaryType type) {
  BoundarySpec s;
  s.patch = std::move(patch);
  s.type = type;
  return s;
}

class BoundaryConditions {
 public:
  // Collective. `nu` is the kinematic viscosity (Womersley profile). Throws
  // std::invalid_argument for a non-periodic patch without a condition (naming it and the
  // accepted types), a condition for a patch the mesh lacks or that is periodic, a bad swap
  // partner, or a Womersley profile without a sine waveform.
  BoundaryConditions(const mesh::LocalMesh& mesh, std::vector<BoundarySpec> specs, double nu);

  // Per local node: 1 where the pressure is fixed (pressure and lumped outlets).
  std::vector<char> pressure_dirichlet() const;
  bool has_pressure_outlet() const { return has_pressure_; }
  // Per local node (`held` resized): 1 where impose() sets the whole velocity (wall and inflow
  // nodes at the time of the last impose()): nodes the projection does not correct.
  void velocity_dirichlet(std::vector<char>& held) const;
  // p = p_out at the pressure-outlet nodes, the held value at lumped-outlet nodes (owned and
  // ghosts).
  void impose_pressure(ScalarField& p) const;
  // The pressure outlet whose value a Dirichlet node takes (patch index; -1 = none): a node on
  // several such patches belongs to a fixed pressure outlet before a lumped one, then to the
  // lowest patch index, so that every lumped outlet's nodes carry one uniform pressure.
  const std::vector<int>& pressure_owner() const { return pressure_owner_; }
  // Lumped outlets: the pressure impose_pressure() gives the nodes of `patch`, Pa.
  void set_outlet_pressure(int patch, double p) { outlet_pressure_[patch] = p; }

  // Collective. Predicted convective-outlet values u^n - dt_stage U_c (grad w) n at time t,
  // held for the next impose().
  void advect_outlets(const VectorField& w, const VectorField& un, double t, double dt_stage);
  // Holds the convective-outlet values of u (the predictor) for impose() after the projection.
  void hold_outlets(const VectorField& u);
  // Collective. Dirichlet values at time t, held outlet values, slip, and the mass correction
  // (owned and ghost nodes).
  void impose(VectorField& u, double t);

  // Backflow stabilisation of pressure outlets (Bazilevs, Gohean, Hughes, Moser & Zhang, Comput.
  // Methods Appl. Mech. Engrg. 198, 3534-3550, 2009, eq. 20; Moghadam et al., Comput. Mech.
  // 48, 277-291, 2011): rhs_j += min(u_j . A_j, 0) u_j / V_j on the outlet faces, nothing where
  // the flow leaves. The centred convective term's boundary flux (u . A) u brings kinetic energy
  // 1/2 |u . A| |u|^2 in where the flow re-enters; half this term removes exactly that, the
  // whole term as much again (a dissipative backflow, beta = 1 in Moghadam et al.'s form).
  // Measured (bench_womersley_study, Wo 17): without it a Womersley pipe blew up within one
  // period; with the half term the pipe at D/10 on a 0.78 h Gmsh mesh, 4 D long, still blew
  // up at t = 0.85 s (flow reversal), with the whole term it runs through it; the D/20 case's
  // errors are unchanged to 3 digits (5.33 % max, 2.51 % L2). `u`, `rhs`: owned and ghost nodes.
  void stabilize_backflow(const VectorField& u, VectorField& rhs) const;
  // Do-nothing (traction-free) viscous flux of pressure outlets: the viscous operators add the
  // boundary flux nu (grad u) . A of every boundary face from the nodal gradient, an
  // extrapolation that feeds the outlet node from its own value; at a pressure outlet the
  // natural condition nu du/dn = (p - p_out) n / rho = 0 sets that flux to zero, so it is taken
  // out again: rhs_j -= (nu + nu_sgs_j) F_j . A_j / V_j, F = grad u (Laplacian form) or
  // grad u + grad u^T (stress form, with LES). `nu_sgs` empty = laminar.
  void drop_outlet_viscous_flux(const TensorField& grad, double nu, const ScalarField& nu_sgs,
                                VectorField& rhs) const;

  // Collective. Outward flux sum u . A through every patch of the mesh (index = patch index
  // of LocalMesh::patch_names), m^3/s; periodic patches get 0.
  std::vector<double> patch_fluxes(const VectorField& u) const;
  // Collective. The patch fluxes that a velocity change du makes after impose() at the time of
  // the last impose(): impose() is affine in u, and this is its linear part (held walls and
  // inflows take nothing, slip nodes lose their normal part, outlets pass du, then the mass
  // correction). Exact to round-off, so that the lumped outlets' implicit coupling
  // (flow/lumped_outlets.hpp) knows how their flux answers their pressure.
  std::vector<double> flux_response(const VectorField& du);
  const std::vector<BoundarySpec>& specs() const { return specs_; }
  // Patch index of each spec.
  const std::vector<int>& spec_patches() const { return spec_patch_; }
  // Flow rate a patch imposes at time t (inlets and swapped partners; 0 otherwise), m^3/s.
  double imposed_inflow(int patch, double t) const;

 private:
  enum class Role { none, fixed, inflow, slip, convective, pressure };
  struct Patch {
    int spec = -1;     // index into specs_, -1 = no condition (periodic)
    int partner = -1;  // inlet: partner patch; convective outlet: the inlet naming it
    Eigen::Vector3d area_vector = Eigen::Vector3d::Zero();  // sum A (outward)
    double area = 0;                                        // sum |A|
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    Eigen::Vector3d inward = Eigen::Vector3d::Zero();  // -area_vector / |area_vector|
    double radius = 0;
    double across_min = 0, across_max = 0;  // plane_poiseuille: extent along `across`
    Womersley womersley;
    Role role = Role::none;  // at the current time
  };
  void update_roles(double t);
  void remove_slip_normals(std::size_t k, Eigen::Vector3d& u) const;
  double profile(const Patch& p, int patch, const Eigen::Vector3d& x, double q, double t,
                 double& shape) const;

  const mesh::LocalMesh& mesh_;
  std::vector<BoundarySpec> specs_;
  std::vector<int> spec_patch_;
  std::vector<Patch> patches_;
  bool has_pressure_ = false, has_convective_ = false;
  // Boundary nodes (owned and ghosts) and their boundary entries, CSR.
  std::vector<int> nodes_, entry_offsets_, entries_;
  // Per boundary node, at the current time: role, the patch giving it, outlet area vector.
  std::vector<Role> role_;
  std::vector<int> role_patch_;
  std::vector<char> slip_;  // slip projection after the value
  bool free_outflow(std::size_t k) const {
    return !slip_[k] && (role_[k] == Role::convective || role_[k] == Role::pressure);
  }
  std::vector<Eigen::Vector3d> outlet_area_;
  std::vector<int> pressure_owner_;                // per local node, see pressure_owner()
  std::vector<double> outlet_pressure_;            // per patch: lumped outlets' held pressure
  VectorField response_;                           // per boundary node: flux_response() scratch
  VectorField held_;                               // per boundary node: convective-outlet value
  TensorField grad_;                               // at the boundary nodes (advect_outlets)
  std::optional<GradientSubset> outlet_gradient_;  // their edges (first advect_outlets)
  std::vector<double> sums_;
};

}  // namespace valsalva::flow
