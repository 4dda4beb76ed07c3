// P1 stiffness or two-point edge weights for the Poisson matrix; see poisson_weights.hpp.
#include "flow/poisson_weights.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "flow/operators.hpp"

namespace valsalva::flow {

std::vector<double> poisson_weights(const Mesh& mesh, const DualMetrics& metrics,
                                    const LocalMesh& local) {
  const bool all_tetra = std::all_of(mesh.cell_types.begin(), mesh.cell_types.end(),
                                     [](CellType t) { return t == CellType::tetra; });
  if (!all_tetra) return laplacian_weights(local);

  const auto n = static_cast<std::uint64_t>(metrics.num_nodes());
  auto key = [n](GlobalIndex a, GlobalIndex b) {
    return static_cast<std::uint64_t>(std::min(a, b)) * n +
           static_cast<std::uint64_t>(std::max(a, b));
  };
  std::unordered_map<std::uint64_t, double> weight;
  weight.reserve(local.edges.size());
  for (const auto& [j, k] : local.edges) weight[key(local.dual_node[j], local.dual_node[k])] = 0.0;

  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
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
      for (int b = a + 1; b < 4; ++b) {
        const auto it = weight.find(
            key(metrics.dual_of_mesh_node[nodes[a]], metrics.dual_of_mesh_node[nodes[b]]));
        if (it != weight.end()) it->second -= volume * g[a].dot(g[b]);
      }
  }
  std::vector<double> w(local.edges.size());
  for (std::size_t e = 0; e < w.size(); ++e)
    w[e] = weight.at(key(local.dual_node[local.edges[e][0]], local.dual_node[local.edges[e][1]]));
  return w;
}

}  // namespace valsalva::flow
