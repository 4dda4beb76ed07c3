#include "mesh/mesh_check.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace valsalva::mesh {
namespace {

// Calls f(volume, local face, global node) for every sub-tetrahedron of cell c.
template <class F>
void for_each_subtet(const Mesh& mesh, GlobalIndex c, F&& f) {
  const auto nodes = mesh.cell(c);
  Eigen::Vector3d xc = Eigen::Vector3d::Zero();
  for (GlobalIndex n : nodes) xc += mesh.nodes[n];
  xc /= static_cast<double>(nodes.size());
  const auto faces = cell_faces(mesh.cell_types[c]);
  for (int lf = 0; lf < static_cast<int>(faces.size()); ++lf) {
    const auto& face = faces[lf];
    const int nf = static_cast<int>(face.size());
    Eigen::Vector3d xf = Eigen::Vector3d::Zero();
    for (int k : face) xf += mesh.nodes[nodes[k]];
    xf /= nf;
    for (int k = 0; k < nf; ++k) {
      const GlobalIndex a = nodes[face[k]], b = nodes[face[(k + 1) % nf]];
      const Eigen::Vector3d& xa = mesh.nodes[a];
      const Eigen::Vector3d& xb = mesh.nodes[b];
      const Eigen::Vector3d m = 0.5 * (xa + xb);
      // Triangles (a, m, f) and (m, b, f) share the face's outward orientation; the cell
      // centroid lies behind them, so n.(p - xc) / 6 is positive for a valid cell.
      f((m - xa).cross(xf - xa).dot(xa - xc) / 6.0, lf, a);
      f((xb - m).cross(xf - m).dot(m - xc) / 6.0, lf, b);
    }
  }
}

// Sorted node indices, padded with the largest index value for triangles.
using FaceKey = std::array<GlobalIndex, 4>;

FaceKey face_key(std::span<const GlobalIndex> nodes) {
  constexpr GlobalIndex pad = std::numeric_limits<GlobalIndex>::max();
  FaceKey key{pad, pad, pad, pad};
  for (std::size_t k = 0; k < nodes.size() && k < key.size(); ++k) key[k] = nodes[k];
  std::sort(key.begin(), key.end());
  return key;
}

struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (GlobalIndex v : k) {
      h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

struct CellFaceUse {
  int count = 0;
  GlobalIndex cell = -1;    // first cell using the face
  int local = -1;           // its local face number
  GlobalIndex cell2 = -1;   // second cell
  GlobalIndex tagged = -1;  // boundary face covering it
};

std::string where(const Mesh& mesh) {
  return fmt::format("mesh '{}'", mesh.source);
}

std::string point(const Eigen::Vector3d& x) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", x.x(), x.y(), x.z());
}

std::string describe_cell(const Mesh& mesh, GlobalIndex c) {
  auto nodes = mesh.cell(c);
  return fmt::format("cell {} ({}, nodes {})", c, name(mesh.cell_types[c]),
                     fmt::join(nodes.begin(), nodes.end(), " "));
}

Eigen::Vector3d centroid(const Mesh& mesh, std::span<const GlobalIndex> nodes) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (GlobalIndex n : nodes) x += mesh.nodes[n];
  return x / static_cast<double>(nodes.size());
}

[[noreturn]] void fail(const Mesh& mesh, const std::string& what) {
  throw MeshError(where(mesh) + ": " + what);
}

void check_structure(const Mesh& mesh) {
  const auto nc = static_cast<std::size_t>(mesh.num_cells());
  const auto nf = static_cast<std::size_t>(mesh.num_faces());
  if (mesh.cell_offsets.size() != nc + 1 || mesh.cell_regions.size() != nc ||
      mesh.cell_offsets.back() != static_cast<GlobalIndex>(mesh.cell_nodes.size()))
    fail(mesh, "inconsistent cell arrays (offsets/regions do not match the cell count)");
  if (mesh.face_offsets.size() != nf + 1 ||
      mesh.face_offsets.back() != static_cast<GlobalIndex>(mesh.face_nodes.size()))
    fail(mesh, "inconsistent boundary face arrays (offsets do not match the face count)");
  if (nc == 0) fail(mesh, "the mesh has no cells");
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    if (static_cast<int>(mesh.cell(c).size()) != node_count(mesh.cell_types[c]))
      fail(mesh, fmt::format("cell {} ({}) has {} nodes", c, name(mesh.cell_types[c]),
                             mesh.cell(c).size()));
    if (mesh.cell_regions[c] < 0 ||
        mesh.cell_regions[c] >= static_cast<int>(mesh.region_names.size()))
      fail(mesh, fmt::format("cell {} has region index {} but the mesh has {} regions", c,
                             mesh.cell_regions[c], mesh.region_names.size()));
  }
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    const auto size = mesh.face(f).size();
    if (size != 3 && size != 4)
      fail(mesh, fmt::format("boundary face {} has {} nodes (3 or 4 expected)", f, size));
    if (mesh.face_patches[f] < 0 ||
        mesh.face_patches[f] >= static_cast<int>(mesh.patch_names.size()))
      fail(mesh, fmt::format("boundary face {} has patch index {} but the mesh has {} patches", f,
                             mesh.face_patches[f], mesh.patch_names.size()));
  }
}

void check_node_indices(const Mesh& mesh) {
  const GlobalIndex n = mesh.num_nodes();
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c)
    for (GlobalIndex v : mesh.cell(c))
      if (v < 0 || v >= n)
        fail(mesh, fmt::format("cell {} ({}) refers to node index {} out of range [0, {})", c,
                               name(mesh.cell_types[c]), v, n));
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f)
    for (GlobalIndex v : mesh.face(f))
      if (v < 0 || v >= n)
        fail(mesh, fmt::format("boundary face {} (patch '{}') refers to node index {} out of "
                               "range [0, {})",
                               f, mesh.patch_names[mesh.face_patches[f]], v, n));
}

void check_cell_shapes(const Mesh& mesh) {
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const double h = longest_edge(mesh, c);
    double volume = 0.0, worst = std::numeric_limits<double>::infinity();
    int worst_face = -1;
    GlobalIndex worst_node = -1;
    for_each_subtet(mesh, c, [&](double v, int lf, GlobalIndex a) {
      volume += v;
      if (v < worst) worst = v, worst_face = lf, worst_node = a;
    });
    if (!(std::abs(volume) >= 1e-12 * h * h * h))
      fail(mesh,
           fmt::format("degenerate {}: volume {:.3g} is below 1e-12 h^3 (h = longest "
                       "edge = {:.3g}) near {}",
                       describe_cell(mesh, c), volume, h, point(centroid(mesh, mesh.cell(c)))));
    if (worst < 0.0)
      fail(mesh, fmt::format("inverted {}: the sub-tetrahedron at node {} of local face {} has "
                             "signed volume {:.3g} (cell volume {:.3g}) near {}",
                             describe_cell(mesh, c), worst_node, worst_face, worst, volume,
                             point(centroid(mesh, mesh.cell(c)))));
  }
}

void check_unused_nodes(const Mesh& mesh) {
  std::vector<char> used(static_cast<std::size_t>(mesh.num_nodes()), 0);
  for (GlobalIndex v : mesh.cell_nodes) used[v] = 1;
  for (GlobalIndex n = 0; n < mesh.num_nodes(); ++n)
    if (!used[n]) {
      const auto unused = std::count(used.begin(), used.end(), 0);
      fail(mesh, fmt::format("unused node {} at {} belongs to no cell ({} unused nodes in all)", n,
                             point(mesh.nodes[n]), unused));
    }
}

using FaceMap = std::unordered_map<FaceKey, CellFaceUse, FaceKeyHash>;

FaceMap collect_cell_faces(const Mesh& mesh) {
  FaceMap faces;
  faces.reserve(static_cast<std::size_t>(mesh.num_cells()) * 3);
  std::vector<GlobalIndex> buffer;
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    const auto local = cell_faces(mesh.cell_types[c]);
    for (int lf = 0; lf < static_cast<int>(local.size()); ++lf) {
      buffer.clear();
      for (int k : local[lf]) buffer.push_back(nodes[k]);
      CellFaceUse& use = faces[face_key(buffer)];
      if (++use.count == 1) {
        use.cell = c, use.local = lf;
      } else if (use.count == 2) {
        use.cell2 = c;
      } else {
        fail(mesh, fmt::format("non-manifold face (nodes {}) near {} is shared by more than two "
                               "cells: {}, {} and {}",
                               fmt::join(buffer, " "), point(centroid(mesh, buffer)), use.cell,
                               use.cell2, c));
      }
    }
  }
  return faces;
}

void match_boundary_faces(const Mesh& mesh, FaceMap& faces) {
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    const auto nodes = mesh.face(f);
    const std::string patch = mesh.patch_names[mesh.face_patches[f]];
    auto it = faces.find(face_key(nodes));
    if (it == faces.end())
      fail(mesh, fmt::format("boundary face {} of patch '{}' (nodes {}) near {} is not a face "
                             "of any cell",
                             f, patch, fmt::join(nodes.begin(), nodes.end(), " "),
                             point(centroid(mesh, nodes))));
    CellFaceUse& use = it->second;
    if (use.count == 2)
      fail(mesh, fmt::format("boundary face {} of patch '{}' (nodes {}) near {} lies inside "
                             "the mesh, between cells {} and {}",
                             f, patch, fmt::join(nodes.begin(), nodes.end(), " "),
                             point(centroid(mesh, nodes)), use.cell, use.cell2));
    if (use.tagged >= 0)
      fail(mesh, fmt::format("boundary face {} of patch '{}' (nodes {}) repeats boundary face "
                             "{} of patch '{}'",
                             f, patch, fmt::join(nodes.begin(), nodes.end(), " "), use.tagged,
                             mesh.patch_names[mesh.face_patches[use.tagged]]));
    use.tagged = f;
  }
}

void check_boundary_covered(const Mesh& mesh, const FaceMap& faces) {
  GlobalIndex missing = 0;
  const CellFaceUse* first = nullptr;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  std::vector<GlobalIndex> buffer;
  auto face_nodes_of = [&](const CellFaceUse& use) {
    buffer.clear();
    for (int k : cell_faces(mesh.cell_types[use.cell])[use.local])
      buffer.push_back(mesh.cell(use.cell)[k]);
  };
  for (const auto& [key, use] : faces) {
    if (use.count != 1 || use.tagged >= 0) continue;
    ++missing;
    if (!first || use.cell < first->cell || (use.cell == first->cell && use.local < first->local))
      first = &use;
    face_nodes_of(use);
    for (GlobalIndex n : buffer) lo = lo.cwiseMin(mesh.nodes[n]), hi = hi.cwiseMax(mesh.nodes[n]);
  }
  if (missing == 0) return;
  face_nodes_of(*first);
  fail(mesh,
       fmt::format("{} boundary faces belong to no boundary patch (missing physical "
                   "group?); they lie in the box {} - {}; first: local face {} of {}, "
                   "face nodes {} near {}",
                   missing, point(lo), point(hi), first->local, describe_cell(mesh, first->cell),
                   fmt::join(buffer, " "), point(centroid(mesh, buffer))));
}

}  // namespace

double cell_volume(const Mesh& mesh, GlobalIndex c) {
  double volume = 0.0;
  for_each_subtet(mesh, c, [&](double v, int, GlobalIndex) { volume += v; });
  return volume;
}

double min_subtet_volume(const Mesh& mesh, GlobalIndex c) {
  double worst = std::numeric_limits<double>::infinity();
  for_each_subtet(mesh, c, [&](double v, int, GlobalIndex) { worst = std::min(worst, v); });
  return worst;
}

Eigen::Vector3d face_area(const Mesh& mesh, std::span<const GlobalIndex> face_nodes) {
  const Eigen::Vector3d xf = centroid(mesh, face_nodes);
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  const std::size_t n = face_nodes.size();
  for (std::size_t k = 0; k < n; ++k)
    area += 0.5 * (mesh.nodes[face_nodes[k]] - xf).cross(mesh.nodes[face_nodes[(k + 1) % n]] - xf);
  return area;
}

double longest_edge(const Mesh& mesh, GlobalIndex c) {
  const auto nodes = mesh.cell(c);
  double longest = 0.0;
  for (const auto& face : cell_faces(mesh.cell_types[c]))
    for (std::size_t k = 0; k < face.size(); ++k)
      longest = std::max(
          longest,
          (mesh.nodes[nodes[face[k]]] - mesh.nodes[nodes[face[(k + 1) % face.size()]]]).norm());
  return longest;
}

void check_mesh(const Mesh& mesh) {
  check_structure(mesh);
  check_node_indices(mesh);
  check_cell_shapes(mesh);
  check_unused_nodes(mesh);
  FaceMap faces = collect_cell_faces(mesh);
  match_boundary_faces(mesh, faces);
  check_boundary_covered(mesh, faces);
}

}  // namespace valsalva::mesh
