// Force of the fluid on a patch; see wall_force.hpp.
#include "flow/wall_force.hpp"

#include <algorithm>
#include <stdexcept>

namespace valsalva::flow {

namespace {

int patch_index(const LocalMesh& mesh, const std::string& patch) {
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

Eigen::Vector3d wall_force(const LocalMesh& mesh, const std::string& patch,
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

  // Owned nodes on the patch.
  std::vector<char> on_patch(mesh.num_local(), 0);
  for (const auto& b : mesh.boundary)
    if (b.patch == p && b.node < mesh.num_owned) on_patch[b.node] = 1;

  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  if (method == WallForceMethod::surface) {
    for (const auto& b : mesh.boundary)
      if (b.patch == p && b.node < mesh.num_owned) {
        const Eigen::Matrix3d& gj = g[b.node];
        force += pr[b.node] * b.area - mu * (gj + gj.transpose()) * b.area;
      }
  } else {
    // -T_j = -(sum conv_out - sum visc_in + sum pres_out - V rho f) over the node's interior
    // dual faces. A node shared with another patch (a corner) gives its whole reaction to this
    // patch: the split is undefined there and such nodes are rare on bodies.
    const auto& a = *in.laplacian_weights;
    for (int e = 0; e < mesh.num_owned_edges; ++e) {
      const auto [j, k] = mesh.edges[e];
      if (!on_patch[j] && !on_patch[k]) continue;
      const Eigen::Vector3d& s = mesh.edge_normal[e];
      const Eigen::Vector3d conv = rho * (0.5 * (u[j] + u[k]).dot(s)) * 0.5 * (u[j] + u[k]);
      Eigen::Vector3d visc = mu * a[e] * (u[k] - u[j]);
      if (!in.stiffness_weights)
        visc += mu * 0.5 * (g[j] + g[k]) * (s - a[e] * mesh.edge_vector[e]);
      const Eigen::Vector3d pres = 0.5 * (pr[j] + pr[k]) * s;
      // Flux out of j through S_jk (and into k).
      const Eigen::Vector3d out_of_j = conv - visc + pres;
      if (on_patch[j]) force -= out_of_j;
      if (on_patch[k]) force += out_of_j;
    }
    if (in.body_force)
      for (int i = 0; i < mesh.num_owned; ++i)
        if (on_patch[i]) force += mesh.volume[i] * (*in.body_force)[i];
  }
  for (int c = 0; c < 3; ++c) force[c] = mesh.comm.sum(force[c]);
  return force;
}

}  // namespace valsalva::flow
