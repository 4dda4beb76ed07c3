// 4th-order gradient, divergence and viscous operators; see operators_order4.hpp.
#include "flow/operators_order4.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace valsalva::flow {

Order4Operators::Order4Operators(const mesh::LocalMesh& mesh, std::vector<double> laplacian_weights)
    : mesh_(mesh), weights_(std::move(laplacian_weights)) {
  if (weights_.size() != mesh.edges.size())
    throw std::invalid_argument("flow::Order4Operators: " + std::to_string(weights_.size()) +
                                " edge weights for " + std::to_string(mesh.edges.size()) +
                                " local edges");
  int deepest = 0;
  for (int layer : mesh.ghost_layer) deepest = std::max(deepest, layer);
  const bool has_ghosts = mesh.num_local() > mesh.num_owned;
  if (mesh.comm.max(std::int64_t{has_ghosts && deepest < 2 ? 1 : 0}) > 0)
    throw std::invalid_argument(
        "flow::Order4Operators: the 4th-order operators need at least 2 ghost layers (their edge "
        "corrections use gradients at the first ghost layer), but the local mesh was built with " +
        std::to_string(deepest) + " on this rank; set partition.ghost_layers = 2 or more");
}

void Order4Operators::gradient(const ScalarField& phi, VectorField& grad) {
  local_gradient(mesh_, phi, grad_s_);
  grad.assign(mesh_.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh_.num_owned_edges; ++e) {
    const auto [j, k] = mesh_.edges[e];
    const Eigen::Vector3d& s = mesh_.edge_normal[e];
    // phi~ - phi_j at j and phi~ - phi_k at k (the latter with S_kj = -S_jk).
    const double half = 0.5 * (phi[k] - phi[j]);
    const double hermite = (grad_s_[j] - grad_s_[k]).dot(mesh_.edge_vector[e]) / 6.0;
    grad[j] += (half + hermite) * s;
    grad[k] += (half - hermite) * s;
  }
  for (int i = 0; i < mesh_.num_owned; ++i)
    grad[i] = mesh_.gradient_correction[i] * grad[i] / mesh_.volume[i];
  const_cast<mesh::Halo&>(mesh_.halo).exchange(grad, mesh::HaloMode::insert);
}

void Order4Operators::divergence(const VectorField& u, ScalarField& div) {
  local_gradient(mesh_, u, grad_v_);
  div.assign(mesh_.num_local(), 0.0);
  for (int e = 0; e < mesh_.num_owned_edges; ++e) {
    const auto [j, k] = mesh_.edges[e];
    const Eigen::Vector3d uf =
        0.5 * (u[j] + u[k]) + (grad_v_[j] - grad_v_[k]) * mesh_.edge_vector[e] / 6.0;
    const double f = uf.dot(mesh_.edge_normal[e]);
    div[j] += f;
    div[k] -= f;
  }
  for (const auto& b : mesh_.boundary) div[b.node] += u[b.node].dot(b.area);
  for (int i = 0; i < mesh_.num_owned; ++i) div[i] /= mesh_.volume[i];
  const_cast<mesh::Halo&>(mesh_.halo).exchange(div, mesh::HaloMode::insert);
}

void Order4Operators::viscous(double nu, const VectorField& v, const TensorField& grad,
                              VectorField& out) {
  const int n = mesh_.num_local();
  if (v.size() != static_cast<std::size_t>(n) || grad.size() != static_cast<std::size_t>(n))
    throw std::invalid_argument("flow::Order4Operators::viscous: " + std::to_string(v.size()) +
                                " velocities and " + std::to_string(grad.size()) +
                                " gradients for " + std::to_string(n) + " local nodes");
  // H = G(G) per velocity component, complete at owned and layer-1 ghost nodes (G is valid at
  // every ghost, so all local edges contribute).
  hessian_.resize(n);
  for (auto& h : hessian_) h.fill(Eigen::Matrix3d::Zero());
  for (std::size_t e = 0; e < mesh_.edges.size(); ++e) {
    const auto [j, k] = mesh_.edges[e];
    const Eigen::Matrix3d dg = 0.5 * (grad[k] - grad[j]);
    for (int c = 0; c < 3; ++c) {
      const Eigen::Matrix3d f = dg.row(c).transpose() * mesh_.edge_normal[e].transpose();
      hessian_[j][c] += f;
      hessian_[k][c] += f;
    }
  }
  for (int i = 0; i < n; ++i)
    for (auto& h : hessian_[i]) h = h * mesh_.gradient_correction[i].transpose() / mesh_.volume[i];

  out.assign(n, Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh_.num_owned_edges; ++e) {
    const auto [j, k] = mesh_.edges[e];
    const Eigen::Vector3d& d = mesh_.edge_vector[e];
    Eigen::Vector3d hermite;
    for (int c = 0; c < 3; ++c) hermite[c] = d.dot((hessian_[k][c] - hessian_[j][c]) * d);
    const Eigen::Vector3d f = weights_[e] * (v[k] - v[j] - hermite / 12.0);
    out[j] += f;
    out[k] -= f;
  }
  for (const auto& b : mesh_.boundary) out[b.node] += grad[b.node] * b.area;
  for (int i = 0; i < mesh_.num_owned; ++i) out[i] *= nu / mesh_.volume[i];
  const_cast<mesh::Halo&>(mesh_.halo).exchange(out, mesh::HaloMode::insert);
}

}  // namespace valsalva::flow
