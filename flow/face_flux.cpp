// Face volume fluxes of the projection; see face_flux.hpp.
#include "flow/face_flux.hpp"

#include <stdexcept>
#include <string>

namespace valsalva::flow {

namespace {

void check_nodal(const mesh::LocalMesh& mesh, std::size_t size, const char* what) {
  if (size != static_cast<std::size_t>(mesh.num_local()))
    throw std::invalid_argument(std::string("flow face flux: ") + what + " has " +
                                std::to_string(size) + " values, the local mesh has " +
                                std::to_string(mesh.num_local()) + " nodes");
}

void check_edges(const mesh::LocalMesh& mesh, std::size_t size, const char* what) {
  if (size != mesh.edges.size())
    throw std::invalid_argument(std::string("flow face flux: ") + what + " has " +
                                std::to_string(size) + " values, the local mesh has " +
                                std::to_string(mesh.edges.size()) + " edges");
}

}  // namespace

void central_face_flux(const mesh::LocalMesh& mesh, const VectorField& u, EdgeField& flux) {
  check_nodal(mesh, u.size(), "velocity");
  flux.resize(mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [j, k] = mesh.edges[e];
    flux[e] = 0.5 * (u[j] + u[k]).dot(mesh.edge_normal[e]);
  }
}

void hermite_face_flux(const mesh::LocalMesh& mesh, const VectorField& u, const TensorField& grad,
                       EdgeField& flux) {
  check_nodal(mesh, u.size(), "velocity");
  check_nodal(mesh, grad.size(), "velocity gradient");
  flux.resize(mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [j, k] = mesh.edges[e];
    const Eigen::Vector3d uf =
        0.5 * (u[j] + u[k]) + (grad[j] - grad[k]) * mesh.edge_vector[e] / 6.0;
    flux[e] = uf.dot(mesh.edge_normal[e]);
  }
}

void face_flux_divergence(const mesh::LocalMesh& mesh, const EdgeField& flux, const VectorField& u,
                          ScalarField& div) {
  check_edges(mesh, flux.size(), "flux");
  check_nodal(mesh, u.size(), "velocity");
  div.assign(mesh.num_local(), 0.0);
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    div[j] += flux[e];
    div[k] -= flux[e];
  }
  for (const auto& b : mesh.boundary) div[b.node] += u[b.node].dot(b.area);
  for (int i = 0; i < mesh.num_owned; ++i) div[i] /= mesh.volume[i];
  for (int i = mesh.num_owned; i < mesh.num_local(); ++i) div[i] = 0;
}

void add_compact_gradient(const mesh::LocalMesh& mesh, const std::vector<double>& weights, double c,
                          const ScalarField& phi, EdgeField& flux) {
  check_edges(mesh, flux.size(), "flux");
  check_edges(mesh, weights.size(), "weights");
  check_nodal(mesh, phi.size(), "phi");
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [j, k] = mesh.edges[e];
    flux[e] += c * weights[e] * (phi[k] - phi[j]);
  }
}

void add_central_flux(const mesh::LocalMesh& mesh, double c, const VectorField& g,
                      EdgeField& flux) {
  check_edges(mesh, flux.size(), "flux");
  check_nodal(mesh, g.size(), "gradient");
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [j, k] = mesh.edges[e];
    flux[e] += c * 0.5 * (g[j] + g[k]).dot(mesh.edge_normal[e]);
  }
}

}  // namespace valsalva::flow
