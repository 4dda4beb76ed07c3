// Edge-based operators; see operators.hpp for the formulas and the source.
#include "flow/operators.hpp"

#include <span>
#include <stdexcept>

namespace valsalva::flow {

namespace {

template <class T>
void finish_field(const mesh::LocalMesh& mesh, std::vector<T>& out, int components) {
  // Ghost accumulations are partial; the owners' values replace them.
  const_cast<mesh::Halo&>(mesh.halo).exchange(
      std::span<double>(reinterpret_cast<double*>(out.data()), components * out.size()), components,
      mesh::HaloMode::insert);
}

void finish_field(const mesh::LocalMesh& mesh, ScalarField& out) {
  const_cast<mesh::Halo&>(mesh.halo).exchange(out, mesh::HaloMode::insert);
}

void check_size(const mesh::LocalMesh& mesh, std::size_t size, const char* what) {
  if (size != static_cast<std::size_t>(mesh.num_local()))
    throw std::invalid_argument(std::string("flow operators: field '") + what + "' has " +
                                std::to_string(size) + " values, the local mesh has " +
                                std::to_string(mesh.num_local()) + " nodes");
}

}  // namespace

std::vector<double> laplacian_weights(const mesh::LocalMesh& mesh) {
  std::vector<double> a(mesh.edges.size());
  for (std::size_t e = 0; e < a.size(); ++e) {
    const auto& s = mesh.edge_normal[e];
    const double sd = s.dot(mesh.edge_vector[e]);
    if (!(sd > 0))
      throw std::runtime_error("flow::laplacian_weights: edge " + std::to_string(e) +
                               " has S.d = " + std::to_string(sd) +
                               " <= 0 (dual face not facing along the edge)");
    a[e] = s.squaredNorm() / sd;
  }
  return a;
}

void gradient(const mesh::LocalMesh& mesh, const ScalarField& phi, VectorField& grad) {
  check_size(mesh, phi.size(), "phi");
  grad.assign(mesh.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const Eigen::Vector3d f = 0.5 * (phi[k] - phi[j]) * mesh.edge_normal[e];
    grad[j] += f;
    grad[k] += f;
  }
  for (int i = 0; i < mesh.num_owned; ++i)
    grad[i] = mesh.gradient_correction[i] * grad[i] / mesh.volume[i];
  finish_field(mesh, grad, 3);
}

namespace {
// One edge's share of the velocity gradient and a node's closure: shared by gradient() and
// gradient_at() so that both give the same bits.
inline void add_gradient_edge(const mesh::LocalMesh& mesh, int e, const VectorField& u,
                              TensorField& grad) {
  const auto [j, k] = mesh.edges[e];
  const Eigen::Matrix3d f = 0.5 * (u[k] - u[j]) * mesh.edge_normal[e].transpose();
  grad[j] += f;
  grad[k] += f;
}
inline void close_gradient(const mesh::LocalMesh& mesh, int i, TensorField& grad) {
  grad[i] = grad[i] * mesh.gradient_correction[i].transpose() / mesh.volume[i];
}
}  // namespace

void gradient(const mesh::LocalMesh& mesh, const VectorField& u, TensorField& grad) {
  check_size(mesh, u.size(), "u");
  grad.assign(mesh.num_local(), Eigen::Matrix3d::Zero());
  for (int e = 0; e < mesh.num_owned_edges; ++e) add_gradient_edge(mesh, e, u, grad);
  for (int i = 0; i < mesh.num_owned; ++i) close_gradient(mesh, i, grad);
  finish_field(mesh, grad, 9);
}

GradientSubset gradient_edges(const mesh::LocalMesh& mesh, const std::vector<int>& nodes) {
  GradientSubset s;
  std::vector<char> in(mesh.num_local(), 0);
  for (const int j : nodes)
    if (j < mesh.num_owned && !in[j]) in[j] = 1, s.nodes.push_back(j);
  for (int e = 0; e < mesh.num_owned_edges; ++e)
    if (in[mesh.edges[e][0]] || in[mesh.edges[e][1]]) s.edges.push_back(e);
  return s;
}

void gradient_at(const mesh::LocalMesh& mesh, const GradientSubset& subset, const VectorField& u,
                 TensorField& grad) {
  check_size(mesh, u.size(), "u");
  grad.resize(mesh.num_local(), Eigen::Matrix3d::Zero());
  // Both ends start from zero, so the other ends' partial sums stay bounded between calls.
  for (const int e : subset.edges)
    for (const int j : mesh.edges[e]) grad[j].setZero();
  for (const int e : subset.edges) add_gradient_edge(mesh, e, u, grad);
  for (const int i : subset.nodes) close_gradient(mesh, i, grad);
  finish_field(mesh, grad, 9);
}

void local_gradient(const mesh::LocalMesh& mesh, const ScalarField& phi, VectorField& grad) {
  grad.assign(mesh.num_local(), Eigen::Vector3d::Zero());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [j, k] = mesh.edges[e];
    const Eigen::Vector3d f = 0.5 * (phi[k] - phi[j]) * mesh.edge_normal[e];
    grad[j] += f;
    grad[k] += f;
  }
  for (int i = 0; i < mesh.num_local(); ++i)
    grad[i] = mesh.gradient_correction[i] * grad[i] / mesh.volume[i];
}

void local_gradient(const mesh::LocalMesh& mesh, const VectorField& u, TensorField& grad) {
  grad.assign(mesh.num_local(), Eigen::Matrix3d::Zero());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [j, k] = mesh.edges[e];
    const Eigen::Matrix3d f = 0.5 * (u[k] - u[j]) * mesh.edge_normal[e].transpose();
    grad[j] += f;
    grad[k] += f;
  }
  for (int i = 0; i < mesh.num_local(); ++i)
    grad[i] = grad[i] * mesh.gradient_correction[i].transpose() / mesh.volume[i];
}

void divergence(const mesh::LocalMesh& mesh, const VectorField& u, ScalarField& div) {
  check_size(mesh, u.size(), "u");
  div.assign(mesh.num_local(), 0.0);
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const double f = 0.5 * (u[j] + u[k]).dot(mesh.edge_normal[e]);
    div[j] += f;
    div[k] -= f;
  }
  for (const auto& b : mesh.boundary) div[b.node] += u[b.node].dot(b.area);
  for (int i = 0; i < mesh.num_owned; ++i) div[i] /= mesh.volume[i];
  finish_field(mesh, div);
}

void laplacian(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
               const ScalarField& phi, const VectorField& grad, ScalarField& lap) {
  check_size(mesh, phi.size(), "phi");
  check_size(mesh, grad.size(), "grad");
  lap.assign(mesh.num_local(), 0.0);
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const Eigen::Vector3d t = mesh.edge_normal[e] - weights[e] * mesh.edge_vector[e];
    const double f = weights[e] * (phi[k] - phi[j]) + 0.5 * t.dot(grad[j] + grad[k]);
    lap[j] += f;
    lap[k] -= f;
  }
  for (const auto& b : mesh.boundary) lap[b.node] += grad[b.node].dot(b.area);
  for (int i = 0; i < mesh.num_owned; ++i) lap[i] /= mesh.volume[i];
  finish_field(mesh, lap);
}

void convection(const mesh::LocalMesh& mesh, const VectorField& u, const VectorField& v,
                VectorField& conv) {
  check_size(mesh, u.size(), "u");
  check_size(mesh, v.size(), "v");
  conv.assign(mesh.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const double flux = 0.5 * (u[j] + u[k]).dot(mesh.edge_normal[e]);
    const Eigen::Vector3d f = flux * 0.5 * (v[j] + v[k]);
    conv[j] += f;
    conv[k] -= f;
  }
  for (const auto& b : mesh.boundary) conv[b.node] += u[b.node].dot(b.area) * v[b.node];
  for (int i = 0; i < mesh.num_owned; ++i) conv[i] /= mesh.volume[i];
  finish_field(mesh, conv, 3);
}

void skew_convection(const mesh::LocalMesh& mesh, const VectorField& u,
                     const std::vector<double>& flux, VectorField& conv) {
  check_size(mesh, u.size(), "u");
  if (flux.size() != mesh.edges.size())
    throw std::invalid_argument("flow::skew_convection: " + std::to_string(flux.size()) +
                                " face fluxes for " + std::to_string(mesh.edges.size()) +
                                " local edges");
  conv.assign(mesh.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const double half = 0.5 * flux[e];
    conv[j] += half * u[k];
    conv[k] -= half * u[j];
  }
  for (const auto& b : mesh.boundary) conv[b.node] += 0.5 * u[b.node].dot(b.area) * u[b.node];
  for (int i = 0; i < mesh.num_owned; ++i) conv[i] /= mesh.volume[i];
  finish_field(mesh, conv, 3);
}

void viscous(const mesh::LocalMesh& mesh, const std::vector<double>& weights, double nu,
             const VectorField& v, const TensorField& grad, VectorField& out, bool correction) {
  check_size(mesh, v.size(), "v");
  check_size(mesh, grad.size(), "grad");
  out.assign(mesh.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    Eigen::Vector3d f = weights[e] * (v[k] - v[j]);
    if (correction)
      f += 0.5 * (grad[j] + grad[k]) * (mesh.edge_normal[e] - weights[e] * mesh.edge_vector[e]);
    out[j] += f;
    out[k] -= f;
  }
  for (const auto& b : mesh.boundary) out[b.node] += grad[b.node] * b.area;
  for (int i = 0; i < mesh.num_owned; ++i) out[i] *= nu / mesh.volume[i];
  finish_field(mesh, out, 3);
}

}  // namespace valsalva::flow
