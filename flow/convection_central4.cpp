// 4th-order centred convection; see convection_central4.hpp for the formulas and sources.
#include "flow/convection_central4.hpp"

#include <algorithm>
#include <stdexcept>

namespace valsalva::flow {

namespace {

double contract(const Eigen::Matrix3d& h, const mesh::SymTensor& m) {
  // H : M for symmetric M stored xx, yy, zz, xy, xz, yz (H symmetrised).
  return h(0, 0) * m[0] + h(1, 1) * m[1] + h(2, 2) * m[2] + (h(0, 1) + h(1, 0)) * m[3] +
         (h(0, 2) + h(2, 0)) * m[4] + (h(1, 2) + h(2, 1)) * m[5];
}

}  // namespace

ConvectionCentral4::ConvectionCentral4(const mesh::LocalMesh& mesh, Form form)
    : mesh_(mesh), form_(form), grad_(mesh.num_local(), Eigen::Matrix3d::Zero()) {
  int deepest = 0;
  for (int layer : mesh.ghost_layer) deepest = std::max(deepest, layer);
  const bool has_ghosts = mesh.num_local() > mesh.num_owned;
  const std::int64_t too_few = has_ghosts && deepest < 2 ? 1 : 0;
  if (mesh.comm.max(too_few) > 0)
    throw std::invalid_argument(
        "flow::ConvectionCentral4: the 4th-order scheme needs at least 2 ghost layers (the "
        "gradients of the first ghost layer use the second), but the local mesh was built with " +
        std::to_string(deepest) +
        " on this rank; set partition.ghost_layers = 2 or more (or use flow.scheme = "
        "\"central2\")");
  if (form_ == Form::deconvolution) {
    nodal_.assign(mesh.num_local(), Eigen::Vector3d::Zero());
    hessian_.resize(mesh.num_local());
  }
}

void ConvectionCentral4::deconvolve(const VectorField& u) {
  local_gradient(mesh_, u, grad_);
  for (int i = 0; i < mesh_.num_owned; ++i) hessian_[i].fill(Eigen::Matrix3d::Zero());
  for (int e = 0; e < mesh_.num_owned_edges; ++e) {
    const auto [j, k] = mesh_.edges[e];
    for (int c = 0; c < 3; ++c) {
      const Eigen::Matrix3d f =
          0.5 * (grad_[k].row(c) - grad_[j].row(c)).transpose() * mesh_.edge_normal[e].transpose();
      if (j < mesh_.num_owned) hessian_[j][c] += f;
      if (k < mesh_.num_owned) hessian_[k][c] += f;
    }
  }
  for (int i = 0; i < mesh_.num_owned; ++i) {
    const double v = mesh_.volume[i];
    for (int c = 0; c < 3; ++c) {
      const Eigen::Matrix3d h = hessian_[i][c] * mesh_.gradient_correction[i].transpose() / v;
      nodal_[i][c] = u[i][c] - grad_[i].row(c).dot(mesh_.first_moment[i]) / v -
                     0.5 * contract(h, mesh_.second_moment[i]) / v;
    }
  }
  const_cast<mesh::Halo&>(mesh_.halo).exchange(nodal_, mesh::HaloMode::insert);
}

void ConvectionCentral4::apply(const VectorField& u, VectorField& conv) {
  if (u.size() != static_cast<std::size_t>(mesh_.num_local()))
    throw std::invalid_argument("flow::ConvectionCentral4: velocity has " +
                                std::to_string(u.size()) + " values, the local mesh has " +
                                std::to_string(mesh_.num_local()) + " nodes");
  conv.assign(mesh_.num_local(), Eigen::Vector3d::Zero());
  if (form_ == Form::edge4) {
    local_gradient(mesh_, u, grad_);
    for (int e = 0; e < mesh_.num_owned_edges; ++e) {
      const auto [j, k] = mesh_.edges[e];
      const Eigen::Vector3d& s = mesh_.edge_normal[e];
      const Eigen::Vector3d du = u[k] - u[j];
      const Eigen::Vector3d uf =
          0.5 * (u[j] + u[k]) + (grad_[j] - grad_[k]) * mesh_.edge_vector[e] / 6.0;
      const Eigen::Vector3d f = uf.dot(s) * uf - du.dot(s) / 12.0 * du;
      conv[j] += f;
      conv[k] -= f;
    }
  } else {
    deconvolve(u);
    local_gradient(mesh_, nodal_, grad_);
    for (int e = 0; e < mesh_.num_owned_edges; ++e) {
      const auto [j, k] = mesh_.edges[e];
      const Eigen::Vector3d uf =
          0.5 * (nodal_[j] + nodal_[k]) + (grad_[j] - grad_[k]) * mesh_.edge_vector[e] / 8.0;
      const Eigen::Vector3d f = uf.dot(mesh_.edge_normal[e]) * uf;
      conv[j] += f;
      conv[k] -= f;
    }
  }
  const VectorField& ub = form_ == Form::edge4 ? u : nodal_;
  for (const auto& b : mesh_.boundary) conv[b.node] += ub[b.node].dot(b.area) * ub[b.node];
  for (int i = 0; i < mesh_.num_owned; ++i) conv[i] /= mesh_.volume[i];
  const_cast<mesh::Halo&>(mesh_.halo).exchange(conv, mesh::HaloMode::insert);
}

void ConvectionCentral4::apply(const VectorField& u, const EdgeField& flux, VectorField& conv) {
  if (form_ != Form::edge4)
    throw std::logic_error(
        "flow::ConvectionCentral4: the deconvolution form has no skew-symmetric form (it is kept "
        "only to measure its truncation order)");
  if (u.size() != static_cast<std::size_t>(mesh_.num_local()) || flux.size() != mesh_.edges.size())
    throw std::invalid_argument("flow::ConvectionCentral4: " + std::to_string(u.size()) +
                                " velocities and " + std::to_string(flux.size()) +
                                " face fluxes for " + std::to_string(mesh_.num_local()) +
                                " nodes and " + std::to_string(mesh_.edges.size()) + " edges");
  const int n = mesh_.num_local();
  local_gradient(mesh_, u, grad_);  // owned and layer-1 ghosts
  // T_i on every local node (complete at owned and layer-1 ghosts: all their edges are local).
  adjoint_.assign(n, Eigen::Matrix3d::Zero());
  for (std::size_t e = 0; e < mesh_.edges.size(); ++e) {
    const auto [j, k] = mesh_.edges[e];
    const Eigen::Matrix3d a = (flux[e] / 6.0) * (u[j] - u[k]) * mesh_.edge_vector[e].transpose();
    adjoint_[j] += a;
    adjoint_[k] -= a;
  }
  for (int i = 0; i < n; ++i)
    adjoint_[i] = adjoint_[i] * mesh_.gradient_correction[i] / mesh_.volume[i];
  conv.assign(n, Eigen::Vector3d::Zero());
  for (int e = 0; e < mesh_.num_owned_edges; ++e) {
    const auto [j, k] = mesh_.edges[e];
    const double half = 0.5 * flux[e];
    // (1/2) [Q - Q^*]: the Hermite flux F (G_j - G_k) d / 6 and the adjoint (W_j + W_k) S / 2.
    const Eigen::Vector3d q = (half / 6.0) * ((grad_[j] - grad_[k]) * mesh_.edge_vector[e]);
    const Eigen::Vector3d q_adj = 0.25 * (adjoint_[j] + adjoint_[k]) * mesh_.edge_normal[e];
    conv[j] += half * u[k] + q + q_adj;
    conv[k] -= half * u[j] + q + q_adj;
  }
  for (const auto& b : mesh_.boundary) conv[b.node] += 0.5 * u[b.node].dot(b.area) * u[b.node];
  for (int i = 0; i < mesh_.num_owned; ++i) conv[i] /= mesh_.volume[i];
  const_cast<mesh::Halo&>(mesh_.halo).exchange(conv, mesh::HaloMode::insert);
}

}  // namespace valsalva::flow
