#include "mesh/mesh_info.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/dual_metrics.hpp"
#include "mesh/mesh_check.hpp"

namespace valsalva::mesh {
namespace {

using mesh::CellType;
using mesh::GlobalIndex;

// For each corner, its three edge neighbours ordered so that det > 0 in a valid cell (Gmsh
// node order).
constexpr int hex_corners[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                   {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
constexpr int prism_corners[6][4] = {{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5},
                                     {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}};
constexpr int pyramid_corners[4][4] = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}};

template <std::size_t N>
double min_scaled_jacobian(const mesh::Mesh& mesh, GlobalIndex c, const int (&corners)[N][4]) {
  const auto nodes = mesh.cell(c);
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& k : corners) {
    const Eigen::Vector3d& x = mesh.nodes[nodes[k[0]]];
    const Eigen::Vector3d e1 = mesh.nodes[nodes[k[1]]] - x, e2 = mesh.nodes[nodes[k[2]]] - x,
                          e3 = mesh.nodes[nodes[k[3]]] - x;
    const double scale = e1.norm() * e2.norm() * e3.norm();
    worst = std::min(worst, scale > 0 ? e1.cross(e2).dot(e3) / scale : 0.0);
  }
  return worst;
}

double tet_mean_ratio(const mesh::Mesh& mesh, GlobalIndex c) {
  const auto n = mesh.cell(c);
  double sum_l2 = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) sum_l2 += (mesh.nodes[n[a]] - mesh.nodes[n[b]]).squaredNorm();
  const double v = mesh::cell_volume(mesh, c);
  if (sum_l2 == 0) return 0;
  return std::copysign(12.0 * std::pow(3.0 * std::abs(v), 2.0 / 3.0) / sum_l2, v);
}

}  // namespace

double cell_quality(const mesh::Mesh& mesh, GlobalIndex c) {
  switch (mesh.cell_types[c]) {
    case CellType::tetra:
      return tet_mean_ratio(mesh, c);
    case CellType::hexa:
      return min_scaled_jacobian(mesh, c, hex_corners);
    case CellType::prism:
      return std::min(1.0, min_scaled_jacobian(mesh, c, prism_corners) / (std::sqrt(3.0) / 2));
    case CellType::pyramid:
      return std::min(1.0, min_scaled_jacobian(mesh, c, pyramid_corners) * std::sqrt(2.0));
  }
  return 0;
}

MeshInfo summarize_mesh(const mesh::Mesh& mesh,
                        std::optional<std::span<const double>> dual_volumes) {
  MeshInfo info;
  info.source = mesh.source;
  info.nodes = mesh.num_nodes();
  info.cells = mesh.num_cells();
  info.boundary_faces = mesh.num_faces();
  for (const auto& name : mesh.patch_names) info.patches.push_back({name, 0, 0.0});
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    auto& patch = info.patches[mesh.face_patches[f]];
    ++patch.faces;
    patch.area += mesh::face_area(mesh, mesh.face(f)).norm();
  }
  for (const auto& name : mesh.region_names) info.regions.emplace_back(name, 0);
  info.min_cell_volume = std::numeric_limits<double>::infinity();
  info.max_cell_volume = -info.min_cell_volume;
  std::array<double, 4> quality_sum{};
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto t = static_cast<std::size_t>(mesh.cell_types[c]);
    ++info.cells_of_type[t];
    ++info.regions[mesh.cell_regions[c]].second;
    const double v = mesh::cell_volume(mesh, c);
    info.volume += v;
    info.min_cell_volume = std::min(info.min_cell_volume, v);
    info.max_cell_volume = std::max(info.max_cell_volume, v);
    const double q = cell_quality(mesh, c);
    auto& s = info.quality[t];
    if (s.count == 0 || q < s.min) s.min = q, s.worst_cell = c;
    s.max = s.count == 0 ? q : std::max(s.max, q);
    ++s.count;
    quality_sum[t] += q;
  }
  for (std::size_t t = 0; t < 4; ++t)
    if (info.quality[t].count > 0) info.quality[t].mean = quality_sum[t] / info.quality[t].count;
  if (dual_volumes && !dual_volumes->empty()) {
    const auto [lo, hi] = std::minmax_element(dual_volumes->begin(), dual_volumes->end());
    info.min_dual_volume = *lo;
    info.max_dual_volume = *hi;
    double sum = 0;
    for (double v : *dual_volumes) sum += v;
    info.dual_volume_sum = sum;
  }
  return info;
}

std::string format_mesh_info(const MeshInfo& info) {
  std::string out = fmt::format("mesh {}\n  nodes {}, cells {}, boundary faces {}\n", info.source,
                                info.nodes, info.cells, info.boundary_faces);
  const char* measure[] = {"mean ratio", "scaled Jacobian (base corners)",
                           "scaled Jacobian / sin 60", "scaled Jacobian"};
  for (std::size_t t = 0; t < 4; ++t) {
    if (info.cells_of_type[t] == 0) continue;
    const auto& q = info.quality[t];
    out += fmt::format(
        "  {:<12} {:>10}   quality ({}): min {:.4f} (cell {}), mean {:.4f}, max {:.4f}\n",
        mesh::name(static_cast<CellType>(t)), info.cells_of_type[t], measure[t], q.min,
        q.worst_cell, q.mean, q.max);
  }
  for (const auto& [name, cells] : info.regions)
    out += fmt::format("  region {:<16} {} cells\n", "'" + name + "'", cells);
  for (const auto& p : info.patches)
    out += fmt::format("  patch  {:<16} {} faces, area {:.6g} m^2\n", "'" + p.name + "'", p.faces,
                       p.area);
  out += fmt::format("  volume {:.6g} m^3 (cells from {:.3g} to {:.3g} m^3)\n", info.volume,
                     info.min_cell_volume, info.max_cell_volume);
  if (info.min_dual_volume)
    out += fmt::format("  dual volumes from {:.3g} to {:.3g} m^3 (sum {:.6g} m^3)\n",
                       *info.min_dual_volume, *info.max_dual_volume, *info.dual_volume_sum);
  return out;
}

std::string mesh_info(const mesh::Mesh& mesh) {
  mesh::check_mesh(mesh);
  const mesh::DualMetrics metrics = mesh::compute_dual_metrics(mesh);
  return format_mesh_info(summarize_mesh(mesh, std::span<const double>(metrics.volume)));
}

}  // namespace valsalva::mesh
