// The pressure damping term per tetrahedron; see damping_cells.hpp.
#include "flow/damping_cells.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace valsalva::flow {

namespace {

constexpr std::array<std::array<int, 2>, 6> edge_pairs{
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

}  // namespace

DampingCells::DampingCells(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                           const mesh::LocalMesh& local)
    : num_edges_(local.edges.size()) {
  std::unordered_map<mesh::GlobalIndex, int> local_of_dual;
  local_of_dual.reserve(local.dual_node.size());
  for (int j = 0; j < local.num_local(); ++j) local_of_dual[local.dual_node[j]] = j;
  const auto n = static_cast<std::uint64_t>(local.num_local());
  std::unordered_map<std::uint64_t, int> edge_of;
  edge_of.reserve(local.edges.size());
  for (std::size_t e = 0; e < local.edges.size(); ++e) {
    const auto [j, k] = local.edges[e];
    edge_of[static_cast<std::uint64_t>(j) * n + static_cast<std::uint64_t>(k)] =
        static_cast<int>(e);
  }
  std::vector<char> on_boundary(static_cast<std::size_t>(local.num_local()), 0);
  for (const auto& f : local.boundary) on_boundary[f.node] = 1;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_types[c] != mesh::CellType::tetra)
      throw std::invalid_argument(fmt::format(
          "flow::DampingCells: cell {} of {} is not a tetrahedron; the damping term is split "
          "into element shares on all-tetrahedral meshes only",
          c, mesh.source));
    const auto nodes = mesh.cell(c);
    Tetra t;
    bool local_cell = true;
    for (int a = 0; a < 4 && local_cell; ++a) {
      const auto it = local_of_dual.find(metrics.dual_of_mesh_node[nodes[a]]);
      local_cell = it != local_of_dual.end();
      if (local_cell) t.node[a] = it->second;
    }
    if (!local_cell) continue;
    for (int a = 0; a < 4; ++a) t.boundary = t.boundary || on_boundary[t.node[a]];
    std::array<Eigen::Vector3d, 4> x;
    for (int a = 0; a < 4; ++a) x[a] = mesh.nodes[nodes[a]];
    Eigen::Matrix3d J;
    for (int d = 0; d < 3; ++d) J.col(d) = x[d + 1] - x[0];
    const double volume = std::abs(J.determinant()) / 6;
    const Eigen::Matrix3d inv = J.inverse();
    std::array<Eigen::Vector3d, 4> g;
    for (int a = 1; a < 4; ++a) g[a] = inv.row(a - 1).transpose();
    g[0] = -(g[1] + g[2] + g[3]);
    const Eigen::Vector3d centroid = (x[0] + x[1] + x[2] + x[3]) / 4;
    for (int i = 0; i < 6; ++i) {
      const auto [a, b] = edge_pairs[i];
      int j = t.node[a], k = t.node[b];
      const bool flipped = j > k;
      if (flipped) std::swap(j, k);
      const auto it =
          edge_of.find(static_cast<std::uint64_t>(j) * n + static_cast<std::uint64_t>(k));
      if (it == edge_of.end())
        throw std::logic_error("flow::DampingCells: a tetrahedron's edge is not a local edge");
      t.edge[i] = it->second;
      t.weight[i] = -volume * g[a].dot(g[b]);
      // The dual face inside T: on each of the two faces of T holding the edge, the triangle
      // (edge midpoint, face centroid, cell centroid), oriented away from node a.
      const Eigen::Vector3d mid = (x[a] + x[b]) / 2;
      Eigen::Vector3d s = Eigen::Vector3d::Zero();
      for (int o = 0; o < 4; ++o) {
        if (o == a || o == b) continue;
        const Eigen::Vector3d face = (x[a] + x[b] + x[o]) / 3;
        Eigen::Vector3d piece = 0.5 * (face - mid).cross(centroid - mid);
        if (piece.dot(x[b] - x[a]) < 0) piece = -piece;
        s += piece;
      }
      t.face[i] = flipped ? Eigen::Vector3d(-s) : s;
    }
    tetras_.push_back(t);
  }
}

void DampingCells::remove(const std::vector<char>& nodes, double c, double c_boundary,
                          const VectorField& grad_p, const ScalarField& p, EdgeField& flux) const {
  for (const auto& t : tetras_) {
    const double ct = t.boundary ? c_boundary : c;
    if (ct == 0 ||
        (!nodes[t.node[0]] && !nodes[t.node[1]] && !nodes[t.node[2]] && !nodes[t.node[3]]))
      continue;
    for (int i = 0; i < 6; ++i) {
      const auto [a, b] = edge_pairs[i];
      int j = t.node[a], k = t.node[b];
      if (j > k) std::swap(j, k);
      flux[t.edge[i]] -=
          ct * (0.5 * t.face[i].dot(grad_p[j] + grad_p[k]) - t.weight[i] * (p[k] - p[j]));
    }
  }
}

std::vector<double> DampingCells::weight_sums(const std::vector<char>& nodes,
                                              double c_boundary) const {
  std::vector<double> w(num_edges_, 0.0);
  for (const auto& t : tetras_) {
    const bool marked = !nodes.empty() && (nodes[t.node[0]] || nodes[t.node[1]] ||
                                           nodes[t.node[2]] || nodes[t.node[3]]);
    const double kept = marked ? 1 - (t.boundary ? c_boundary : 1.0) : 1.0;
    for (int i = 0; i < 6; ++i) w[t.edge[i]] += kept * t.weight[i];
  }
  return w;
}

std::vector<Eigen::Vector3d> DampingCells::face_sums() const {
  std::vector<Eigen::Vector3d> s(num_edges_, Eigen::Vector3d::Zero());
  for (const auto& t : tetras_)
    for (int i = 0; i < 6; ++i) s[t.edge[i]] += t.face[i];
  return s;
}

}  // namespace valsalva::flow
