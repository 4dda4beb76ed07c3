// Full-stress viscous term with variable viscosity; see viscous_stress.hpp.
#include "flow/viscous_stress.hpp"

#include <stdexcept>
#include <string>

namespace valsalva::flow {

void viscous_stress(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                    const ScalarField& nu, const VectorField& v, const TensorField& grad,
                    VectorField& out) {
  const auto n = static_cast<std::size_t>(mesh.num_local());
  if (nu.size() != n || v.size() != n || grad.size() != n || weights.size() != mesh.edges.size())
    throw std::invalid_argument(
        "flow::viscous_stress: " + std::to_string(nu.size()) + " viscosities, " +
        std::to_string(v.size()) + " velocities, " + std::to_string(grad.size()) +
        " gradients and " + std::to_string(weights.size()) + " edge weights for " +
        std::to_string(n) + " local nodes and " + std::to_string(mesh.edges.size()) + " edges");
  out.assign(n, Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const Eigen::Vector3d& s = mesh.edge_normal[e];
    const Eigen::Vector3d t = s - weights[e] * mesh.edge_vector[e];
    const Eigen::Matrix3d g = 0.5 * (grad[j] + grad[k]);
    const Eigen::Vector3d f =
        (0.5 * (nu[j] + nu[k])) * (weights[e] * (v[k] - v[j]) + g * t + g.transpose() * s);
    out[j] += f;
    out[k] -= f;
  }
  for (const auto& b : mesh.boundary)
    out[b.node] += nu[b.node] * (grad[b.node] + grad[b.node].transpose()) * b.area;
  for (int i = 0; i < mesh.num_owned; ++i) out[i] /= mesh.volume[i];
  // Ghost accumulations are partial; the owners' values replace them.
  const_cast<mesh::Halo&>(mesh.halo).exchange(out, mesh::HaloMode::insert);
}

}  // namespace valsalva::flow
