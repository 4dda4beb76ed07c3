// Force of the fluid on a patch; see wall_force.hpp.
#include "flow/wall_force.hpp"

#include <algorithm>
#include <stdexcept>

namespace valsalva::flow {

namespace {

int patch_index(const mesh::LocalMesh& mesh, const std::string& patch) {
  const auto it = std::find(mesh.patch_names.begin(), mesh.patch_names.end(), patch);
  if (it == mesh.patch_names.end()) {
    std::string names;
    for (const auto& n : mesh.patch_names) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument("flow::wall_force: patch '" + patch +
                                "' is not in the mesh (patches: " + names + ")");
  }
  return static_cast<int>(it - mesh.patch_names.begin());
}

}  // namespace

std::vector<WallLoad> wall_loads(const mesh::LocalMesh& mesh, const std::string& patch,
                                 const WallForceInput& in, WallForceMethod method) {
  if (!in.velocity || !in.pressure || !in.velocity_gradient ||
      (method == WallForceMethod::residual && !in.laplacian_weights))
    throw std::invalid_argument(
        "flow::wall_force: velocity, pressure, velocity gradient and (for the residual method) "
        "Laplacian weights are required");
  const int p = patch_index(mesh, patch);
  const auto& u = *in.velocity;
  const auto& pr = *in.pressure;
  const auto& g = *in.velocity_gradient;
  const double mu = in.dynamic_viscosity, rho = in.density;

  // Owned nodes on the patch, with the area vector of their faces on it and of their faces on
  // other patches (a rim, where the wall meets an inlet, an outlet or another wall).
  std::vector<int> slot(mesh.num_local(), -1);
  std::vector<WallLoad> loads;
  for (const auto& b : mesh.boundary)
    if (b.patch == p && b.node < mesh.num_owned) {
      if (slot[b.node] < 0) {
        slot[b.node] = static_cast<int>(loads.size());
        loads.push_back({b.node, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
      }
      loads[slot[b.node]].area += b.area;
    }
  std::vector<Eigen::Vector3d> other_area(loads.size(), Eigen::Vector3d::Zero());
  for (const auto& b : mesh.boundary)
    if (b.patch != p && b.node < mesh.num_owned && slot[b.node] >= 0)
      other_area[slot[b.node]] += b.area;

  const ScalarField* mu_field = in.viscosity_field;
  if (mu_field && in.stiffness_weights)
    throw std::invalid_argument(
        "flow::wall_force: a nodal viscosity goes with the full-stress operator's two-point "
        "weights, not the stiffness weights");
  if (method == WallForceMethod::surface) {
    for (auto& l : loads) {
      const Eigen::Matrix3d& gj = g[l.node];
      const double mu_j = mu_field ? (*mu_field)[l.node] : mu;
      l.force = pr[l.node] * l.area - mu_j * (gj + gj.transpose()) * l.area;
    }
    return loads;
  }
  // Force on the wall = -T_j = V_j f_j - sum_k (conv_out - visc_in + pres_out) over the interior
  // dual faces of the node: the reaction of all its boundary faces. Where the node also has faces
  // on other patches their pressure load p_j A_other is taken out (at an arterial pressure it
  // dwarfs the shear and, on a rim, lies along the wall); their viscous traction, of the order of
  // the wall shear itself, stays with this patch: the split is undefined there.
  const auto& a = *in.laplacian_weights;
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    if (slot[j] < 0 && slot[k] < 0) continue;
    const Eigen::Vector3d& s = mesh.edge_normal[e];
    const Eigen::Vector3d conv = rho * (0.5 * (u[j] + u[k]).dot(s)) * 0.5 * (u[j] + u[k]);
    Eigen::Vector3d visc;
    if (mu_field) {  // the flux of flow::viscous_stress
      const Eigen::Matrix3d gm = 0.5 * (g[j] + g[k]);
      visc = (0.5 * ((*mu_field)[j] + (*mu_field)[k])) *
             (a[e] * (u[k] - u[j]) + gm * (s - a[e] * mesh.edge_vector[e]) + gm.transpose() * s);
    } else {
      visc = mu * a[e] * (u[k] - u[j]);
      if (!in.stiffness_weights)
        visc += mu * 0.5 * (g[j] + g[k]) * (s - a[e] * mesh.edge_vector[e]);
    }
    const Eigen::Vector3d pres = 0.5 * (pr[j] + pr[k]) * s;
    const Eigen::Vector3d out_of_j = conv - visc + pres;  // through S_jk, into k
    if (slot[j] >= 0) loads[slot[j]].force -= out_of_j;
    if (slot[k] >= 0) loads[slot[k]].force += out_of_j;
  }
  for (std::size_t i = 0; i < loads.size(); ++i)
    loads[i].force -= pr[loads[i].node] * other_area[i];
  if (in.body_force)
    for (auto& l : loads) l.force += mesh.volume[l.node] * (*in.body_force)[l.node];
  return loads;
}

Eigen::Vector3d wall_force(const mesh::LocalMesh& mesh, const std::string& patch,
                           const WallForceInput& in, WallForceMethod method) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const auto& l : wall_loads(mesh, patch, in, method)) force += l.force;
  for (int c = 0; c < 3; ++c) force[c] = mesh.comm.sum(force[c]);
  return force;
}

}  // namespace valsalva::flow
