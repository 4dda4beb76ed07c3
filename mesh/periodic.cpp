#include "mesh/periodic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "core/bucket_grid.hpp"

namespace valsalva::mesh {

namespace {

std::vector<GlobalIndex> patch_nodes(const Mesh& mesh, int patch) {
  std::vector<GlobalIndex> nodes;
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f)
    if (mesh.face_patches[f] == patch)
      for (GlobalIndex n : mesh.face(f)) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

double bounding_box_diagonal(const Mesh& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const auto& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return mesh.nodes.empty() ? 1.0 : (hi - lo).norm();
}

}  // namespace

PeriodicMap match_periodic_nodes(const Mesh& mesh, double relative_tolerance) {
  PeriodicMap map;
  const GlobalIndex n = mesh.num_nodes();
  map.representative.resize(n);
  map.shift.assign(n, Eigen::Vector3d::Zero());
  for (GlobalIndex i = 0; i < n; ++i) map.representative[i] = i;
  if (mesh.periodic.empty()) return map;
  map.any = true;

  const double tol = relative_tolerance * bounding_box_diagonal(mesh);
  // Union-find with offsets: x_i = x_parent[i] + offset[i]; the lowest node index of each set
  // becomes its representative (the corner of the master patches).
  std::vector<GlobalIndex> parent(n);
  std::vector<Eigen::Vector3d> offset(n, Eigen::Vector3d::Zero());
  for (GlobalIndex i = 0; i < n; ++i) parent[i] = i;
  auto find = [&](GlobalIndex i) {
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    while (parent[i] != i) {
      total += offset[i];
      i = parent[i];
    }
    return std::pair{i, total};
  };
  auto unite = [&](GlobalIndex a, GlobalIndex b, const Eigen::Vector3d& t) {  // x_a = x_b + t
    auto [ra, oa] = find(a);
    auto [rb, ob] = find(b);
    const Eigen::Vector3d root_shift = ob + t - oa;  // x_ra = x_rb + root_shift
    if (ra == rb) {
      if (root_shift.norm() > tol)
        throw std::runtime_error(fmt::format(
            "{}: periodic pairs are inconsistent at node {}: it maps onto itself shifted by "
            "({:.6g}, {:.6g}, {:.6g})",
            mesh.source, a, root_shift[0], root_shift[1], root_shift[2]));
      return;
    }
    if (rb < ra) {
      parent[ra] = rb;
      offset[ra] = root_shift;
    } else {
      parent[rb] = ra;
      offset[rb] = -root_shift;
    }
  };

  for (const auto& link : mesh.periodic) {
    const int master = mesh.patch_index(link.master);
    const int slave = mesh.patch_index(link.slave);
    if (master < 0 || slave < 0)
      throw std::runtime_error(
          fmt::format("{}: periodic pair '{}' -> '{}': patch '{}' does not exist in the mesh",
                      mesh.source, link.master, link.slave, master < 0 ? link.master : link.slave));
    const auto master_nodes = patch_nodes(mesh, master);
    const auto slave_nodes = patch_nodes(mesh, slave);
    // Nearest master node within the tolerance (the spatial index makes matching O(n)); the
    // lower node id on a tie. Buckets well above the tolerance (the grid widens them further on
    // a patch much larger than that).
    std::vector<Eigen::Vector3d> master_points(master_nodes.size());
    for (std::size_t k = 0; k < master_nodes.size(); ++k)
      master_points[k] = mesh.nodes[master_nodes[k]];
    const core::BucketGrid grid(master_points, std::max(tol * 16.0, 1e-300));
    for (GlobalIndex s : slave_nodes) {
      const Eigen::Vector3d target = mesh.nodes[s] - link.translation;
      const auto nearest = grid.nearest(target, tol, [](int) { return true; });
      const GlobalIndex found = nearest.index < 0 ? -1 : master_nodes[nearest.index];
      if (found < 0)
        throw std::runtime_error(fmt::format(
            "{}: unmatched periodic node {} at ({:.9g}, {:.9g}, {:.9g}) on patch '{}': no node of "
            "patch '{}' at ({:.9g}, {:.9g}, {:.9g}) within {:.3g} m",
            mesh.source, s, mesh.nodes[s][0], mesh.nodes[s][1], mesh.nodes[s][2], link.slave,
            link.master, target[0], target[1], target[2], tol));
      if (found != s) unite(s, found, link.translation);
    }
  }
  for (GlobalIndex i = 0; i < n; ++i) {
    auto [root, shift] = find(i);
    map.representative[i] = root;
    map.shift[i] = shift;
  }
  return map;
}

}  // namespace valsalva::mesh
