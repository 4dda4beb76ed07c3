// Force of the fluid on a boundary patch (drag and lift of a body, load on a wall), two ways:
//
// - `surface`: the traction integral F = sum_b (p_j A_b - mu (grad u_j + grad u_j^T) A_b) over
//   the patch's boundary dual faces, with nodal p and the nodal velocity gradient (one-sided at
//   the wall, exact for linear fields only: the wall shear is first-order accurate).
// - `residual` (default): the consistent, "reaction" force. The momentum balance of the dual
//   volume of a wall node j with fixed velocity reads 0 = -sum_k conv_jk + sum_k visc_jk -
//   sum_k pres_jk + V_j f_j + T_j, with the interior dual-face fluxes of the flow operators
//   (2nd-order centred convection, two-point + non-orthogonal viscous flux, centred pressure
//   flux) and T_j the unknown wall traction on the fluid; the force on the body is -sum_j T_j.
//   It inherits the accuracy of the interior fluxes instead of a one-sided wall gradient, the
//   property that makes reaction forces the method of choice for drag and lift in finite
//   elements (Giles, Larson, Levenstam & Süli, "Adaptive error control for finite element
//   approximations of the lift and drag coefficients in viscous flow", 1997) and is how
//   node-centred codes recover wall loads. Valid for walls whose velocity does not change in
//   time (du_j/dt = 0 at the wall nodes), like the DFG cylinder or a fixed valve housing.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

enum class WallForceMethod { residual, surface };

struct WallForceInput {
  double density = 1;            // kg/m^3
  double dynamic_viscosity = 0;  // Pa s
  const VectorField* velocity = nullptr;
  const ScalarField* pressure = nullptr;
  const TensorField* velocity_gradient = nullptr;  // flow::gradient of the velocity
  // Viscous edge weights of the residual method: flow::laplacian_weights (two-point weight plus
  // the non-orthogonal correction with nodal gradients), or, on all-tetrahedral meshes, the P1
  // stiffness weights of flow::poisson_weights with `stiffness_weights = true` (no correction:
  // the median-dual flux of the piecewise-linear field, consistent on any tetrahedral mesh).
  const std::vector<double>* laplacian_weights = nullptr;
  bool stiffness_weights = false;
  const VectorField* body_force = nullptr;  // force per unit volume, N/m^3; optional
  // Non-Newtonian fluids: the dynamic viscosity of every local node (Pa s), in place of
  // dynamic_viscosity. The residual method then uses the solver's full-stress flux
  // (flow/viscous_stress.hpp: edge viscosity (mu_j + mu_k)/2, with the transpose part; two-point
  // weights only), the surface method mu_j.
  const ScalarField* viscosity_field = nullptr;
};

// The force (N) of the fluid on the wall share of each owned node of a patch, with the node's
// outward (fluid -> wall) area vector on that patch; the pieces of wall_force and of the wall
// shear stress (flow/wall_shear.hpp).
struct WallLoad {
  int node = 0;  // local node
  Eigen::Vector3d force{0, 0, 0};
  Eigen::Vector3d area{0, 0, 0};
};
std::vector<WallLoad> wall_loads(const mesh::LocalMesh& mesh, const std::string& patch,
                                 const WallForceInput& in,
                                 WallForceMethod method = WallForceMethod::residual);

// Total force (N) of the fluid on patch `patch` (a name of LocalMesh::patch_names), summed over
// all ranks (collective). Throws std::invalid_argument for an unknown patch or missing input.
Eigen::Vector3d wall_force(const mesh::LocalMesh& mesh, const std::string& patch,
                           const WallForceInput& in,
                           WallForceMethod method = WallForceMethod::residual);

}  // namespace valsalva::flow
