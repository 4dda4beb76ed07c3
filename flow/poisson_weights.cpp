// P1 stiffness or two-point edge weights for the Poisson matrix; see poisson_weights.hpp.
#include "flow/poisson_weights.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <unordered_map>

#include "flow/operators.hpp"

namespace valsalva::flow {

namespace {

// -int grad N_a . grad N_b over a tetrahedron, added to weight(a, b) for its six edges.
template <class Add>
void add_tetra(const mesh::Mesh& mesh, std::span<const mesh::GlobalIndex> nodes, Add add) {
  Eigen::Matrix3d J;
  for (int d = 0; d < 3; ++d) J.col(d) = mesh.nodes[nodes[d + 1]] - mesh.nodes[nodes[0]];
  const double volume = std::abs(J.determinant()) / 6;
  // Gradients of the barycentric functions N_1..N_3 are the rows of J^-1; N_0 = 1 - sum.
  const Eigen::Matrix3d inv = J.inverse();
  std::array<Eigen::Vector3d, 4> g;
  g[1] = inv.row(0).transpose();
  g[2] = inv.row(1).transpose();
  g[3] = inv.row(2).transpose();
  g[0] = -(g[1] + g[2] + g[3]);
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) add(nodes[a], nodes[b], -volume * g[a].dot(g[b]));
}

// The lumped tensor-product weights of a right prism (see slab_stiffness_weights).
template <class Add>
void add_prism(const mesh::Mesh& mesh, std::span<const mesh::GlobalIndex> nodes, Add add) {
  const auto x = [&](int i) -> const Eigen::Vector3d& { return mesh.nodes[nodes[i]]; };
  const Eigen::Vector3d axis = x(3) - x(0);
  const double h = axis.norm();
  for (int i = 1; i < 3; ++i)
    if ((x(i + 3) - x(i) - axis).norm() > 1e-9 * h)
      throw std::invalid_argument("slab_stiffness_weights: a prism of " + mesh.source +
                                  " is not a right translation of its bottom triangle");
  const Eigen::Vector3d e = axis / h;
  std::array<Eigen::Vector3d, 3> p;  // the section, projected normal to the axis
  for (int i = 0; i < 3; ++i) p[i] = x(i) - x(i).dot(e) * e;
  const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;  // edge i-j, opposite vertex k
    const Eigen::Vector3d u = p[i] - p[k], v = p[j] - p[k];
    const double w = 0.5 * h * 0.5 * u.dot(v) / u.cross(v).norm();
    add(nodes[i], nodes[j], w);
    add(nodes[i + 3], nodes[j + 3], w);
    add(nodes[i], nodes[i + 3], area / 3 / h);
  }
}

std::vector<double> stiffness_weights(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                                      const mesh::LocalMesh& local) {
  const auto n = static_cast<std::uint64_t>(metrics.num_nodes());
  auto key = [n](mesh::GlobalIndex a, mesh::GlobalIndex b) {
    return static_cast<std::uint64_t>(std::min(a, b)) * n +
           static_cast<std::uint64_t>(std::max(a, b));
  };
  std::unordered_map<std::uint64_t, double> weight;
  weight.reserve(local.edges.size());
  for (const auto& [j, k] : local.edges) weight[key(local.dual_node[j], local.dual_node[k])] = 0.0;

  const auto add = [&](mesh::GlobalIndex a, mesh::GlobalIndex b, double w) {
    const auto it = weight.find(key(metrics.dual_of_mesh_node[a], metrics.dual_of_mesh_node[b]));
    if (it != weight.end()) it->second += w;
  };
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_types[c] == mesh::CellType::tetra)
      add_tetra(mesh, mesh.cell(c), add);
    else
      add_prism(mesh, mesh.cell(c), add);
  }
  std::vector<double> w(local.edges.size());
  for (std::size_t e = 0; e < w.size(); ++e)
    w[e] = weight.at(key(local.dual_node[local.edges[e][0]], local.dual_node[local.edges[e][1]]));
  return w;
}

bool only(const mesh::Mesh& mesh, std::initializer_list<mesh::CellType> types) {
  return std::all_of(mesh.cell_types.begin(), mesh.cell_types.end(), [&](mesh::CellType t) {
    return std::find(types.begin(), types.end(), t) != types.end();
  });
}

}  // namespace

std::vector<double> poisson_weights(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                                    const mesh::LocalMesh& local) {
  if (!only(mesh, {mesh::CellType::tetra})) return laplacian_weights(local);
  return stiffness_weights(mesh, metrics, local);
}

std::vector<double> slab_stiffness_weights(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                                           const mesh::LocalMesh& local) {
  if (!only(mesh, {mesh::CellType::tetra, mesh::CellType::prism}))
    throw std::invalid_argument("slab_stiffness_weights: " + mesh.source +
                                " holds cells other than tetrahedra and prisms");
  return stiffness_weights(mesh, metrics, local);
}

}  // namespace valsalva::flow
