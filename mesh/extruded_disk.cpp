// Gmsh disk triangulation and its extrusion into prisms; see extruded_disk.hpp.
#include "mesh/extruded_disk.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "mesh/gmsh_reader.hpp"

namespace valsalva::mesh {

namespace {

void check_grading(const DiskWallGrading& g, double size) {
  const auto bad = [](double v) { return !(v >= 0.0) || !std::isfinite(v); };
  if (bad(g.wall_size) || bad(g.wall_distance) || bad(g.layer_first) || bad(g.layer_thickness))
    throw std::invalid_argument("triangulate_disk: wall grading sizes must be finite and >= 0");
  if (g.wall_size > 0 && !(g.wall_distance > 0 && g.wall_size < size))
    throw std::invalid_argument(fmt::format(
        "triangulate_disk: wall_size {} needs wall_distance > 0 and wall_size < size {}",
        g.wall_size, size));
  if (g.layer_first > 0 &&
      !(g.layer_thickness >= g.layer_first && g.layer_ratio >= 1 && std::isfinite(g.layer_ratio)))
    throw std::invalid_argument(fmt::format(
        "triangulate_disk: layer_first {} needs layer_thickness >= it and layer_ratio >= 1",
        g.layer_first));
}

// The size fields of the grading on the current model (one disk surface, its circle `curve`).
void add_grading(const DiskWallGrading& g, double radius, double size, int curve) {
  if (g.wall_size > 0) {
    const int field = gmsh::model::mesh::field::add("MathEval");
    gmsh::model::mesh::field::setString(
        field, "F",
        fmt::format("Min({1:.17g}, {0:.17g} + ({1:.17g} - {0:.17g}) * Max(0, {2:.17g} - "
                    "Sqrt(x * x + y * y)) / {3:.17g})",
                    g.wall_size, size, radius, g.wall_distance));
    gmsh::model::mesh::field::setAsBackgroundMesh(field);
    // The bulk keeps `size`: the small wall size must not spread inwards.
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  }
  if (g.layer_first > 0) {
    const int field = gmsh::model::mesh::field::add("BoundaryLayer");
    gmsh::model::mesh::field::setNumbers(field, "CurvesList", {static_cast<double>(curve)});
    gmsh::model::mesh::field::setNumber(field, "hwall_n", g.layer_first);
    gmsh::model::mesh::field::setNumber(field, "ratio", g.layer_ratio);
    gmsh::model::mesh::field::setNumber(field, "thickness", g.layer_thickness);
    gmsh::model::mesh::field::setNumber(field, "hfar", size);
    gmsh::model::mesh::field::setNumber(field, "Quads", 0);
    gmsh::model::mesh::field::setAsBoundaryLayer(field);
  }
}

}  // namespace

Disk triangulate_disk(double radius, double size, const DiskWallGrading& grading,
                      const std::string& source) {
  check_grading(grading, size);
  GmshSession session;
  return gmsh_call(source, [&] {
    gmsh::model::add("disk");
    const int surface = gmsh::model::occ::addDisk(0, 0, 0, radius, radius);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair curves;
    gmsh::model::getBoundary({{2, surface}}, curves, false, false, false);
    if (curves.size() != 1) throw MeshFileError(source + ": expected one circle from OpenCASCADE");
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
    add_grading(grading, radius, size, std::abs(curves[0].second));
    generate_deterministic_mesh(2);
    Disk disk;
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric);
    std::unordered_map<std::size_t, int> index;
    for (std::size_t i = 0; i < tags.size(); ++i) {
      index[tags[i]] = static_cast<int>(i);
      disk.nodes.emplace_back(coords[3 * i], coords[3 * i + 1]);
    }
    std::vector<std::size_t> elements, element_nodes;
    gmsh::model::mesh::getElementsByType(2, elements, element_nodes);  // 3-node triangles
    for (std::size_t e = 0; e < elements.size(); ++e) {
      std::array<int, 3> t{index.at(element_nodes[3 * e]), index.at(element_nodes[3 * e + 1]),
                           index.at(element_nodes[3 * e + 2])};
      const Eigen::Vector2d a = disk.nodes[t[1]] - disk.nodes[t[0]];
      const Eigen::Vector2d b = disk.nodes[t[2]] - disk.nodes[t[0]];
      if (a.x() * b.y() - a.y() * b.x() < 0) std::swap(t[1], t[2]);
      disk.triangles.push_back(t);
    }
    if (disk.triangles.empty()) throw MeshFileError(source + ": Gmsh gave no triangles");
    // Keep only the nodes of triangles, in Gmsh's order (it may hold others).
    std::vector<int> renumber(disk.nodes.size(), -1);
    for (const auto& t : disk.triangles)
      for (int a : t) renumber[a] = 0;
    std::vector<Eigen::Vector2d> kept;
    for (std::size_t a = 0; a < disk.nodes.size(); ++a)
      if (renumber[a] == 0)
        renumber[a] = static_cast<int>(kept.size()), kept.push_back(disk.nodes[a]);
    for (auto& t : disk.triangles)
      for (int& a : t) a = renumber[a];
    disk.nodes = std::move(kept);
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> other_tags, other_nodes;
    gmsh::model::mesh::getElements(types, other_tags, other_nodes, 2);
    for (int type : types)
      if (type != 2)
        throw MeshFileError(
            fmt::format("{}: Gmsh gave 2D elements of type {}, not only triangles", source, type));
    return disk;
  });
}

mesh::Mesh extrude_disk(const Disk& disk, const std::vector<double>& z, const std::string& bottom,
                        const std::string& top, const std::string& source) {
  if (z.size() < 2)
    throw std::invalid_argument(source + ": extrude_disk needs at least two z levels");
  for (std::size_t l = 1; l < z.size(); ++l)
    if (!(z[l] > z[l - 1]))
      throw std::invalid_argument(source + ": extrude_disk needs increasing z levels");
  const auto n = static_cast<mesh::GlobalIndex>(disk.nodes.size());
  const int layers = static_cast<int>(z.size()) - 1;
  mesh::Mesh mesh;
  mesh.source = source;
  mesh.add_region("fluid");
  const int wall = mesh.add_patch("wall"), zmin = mesh.add_patch(bottom),
            zmax = mesh.add_patch(top);
  for (double level : z)
    for (const auto& p : disk.nodes) mesh.nodes.emplace_back(p.x(), p.y(), level);
  const auto at = [n](int node, int layer) { return layer * n + node; };
  // Disk boundary edges: the triangle sides used once, in counter-clockwise order (interior on
  // the left), so the wall quad (a, b, b', a') faces outwards.
  std::map<std::pair<int, int>, int> sides;
  for (const auto& t : disk.triangles)
    for (int i = 0; i < 3; ++i) ++sides[std::minmax(t[i], t[(i + 1) % 3])];
  std::vector<std::pair<int, int>> boundary;
  for (const auto& t : disk.triangles)
    for (int i = 0; i < 3; ++i)
      if (sides[std::minmax(t[i], t[(i + 1) % 3])] == 1)
        boundary.emplace_back(t[i], t[(i + 1) % 3]);
  for (int l = 0; l < layers; ++l) {
    for (const auto& t : disk.triangles) {
      const std::array<mesh::GlobalIndex, 6> prism{
          at(t[0], l), at(t[1], l), at(t[2], l), at(t[0], l + 1), at(t[1], l + 1), at(t[2], l + 1)};
      mesh.add_cell(mesh::CellType::prism, prism);
    }
    for (const auto& [a, b] : boundary) {
      const std::array<mesh::GlobalIndex, 4> quad{at(a, l), at(b, l), at(b, l + 1), at(a, l + 1)};
      mesh.add_face(quad, wall);
    }
  }
  for (const auto& t : disk.triangles) {
    const std::array<mesh::GlobalIndex, 3> lower{at(t[0], 0), at(t[2], 0), at(t[1], 0)};
    const std::array<mesh::GlobalIndex, 3> upper{at(t[0], layers), at(t[1], layers),
                                                 at(t[2], layers)};
    mesh.add_face(lower, zmin);
    mesh.add_face(upper, zmax);
  }
  return mesh;
}

}  // namespace valsalva::mesh
