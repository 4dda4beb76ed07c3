// Extruded periodic pipe mesh; see periodic_pipe_generator.hpp.
#include "io/periodic_pipe_generator.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "io/gmsh_reader.hpp"
#include "io/prism_split.hpp"

namespace valsalva::io {

namespace {

struct Disk {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from +z
};

Disk triangulate_disk(double radius, double size, const std::string& source) {
  GmshSession session;
  return gmsh_call(source, [&] {
    gmsh::model::add("disk");
    gmsh::model::occ::addDisk(0, 0, 0, radius, radius);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
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
    return disk;
  });
}

}  // namespace

flow::Mesh generate_periodic_pipe_mesh(const PeriodicPipeSpec& s) {
  for (const auto& [name, value] :
       {std::pair{"radius", s.radius}, {"length", s.length}, {"target_size", s.target_size}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format(
          "generate_periodic_pipe_mesh: {} must be positive and finite, got {}", name, value));
  if (s.layers < 3)
    throw std::invalid_argument(fmt::format(
        "generate_periodic_pipe_mesh: layers = {}; at least 3 are needed so that a periodic "
        "node and its image are not neighbours",
        s.layers));
  const std::string source =
      fmt::format("periodic_pipe(radius={:g}, length={:g}, size={:g}, layers={}, {})", s.radius,
                  s.length, s.target_size, s.layers, s.split ? "tetra" : "prism");
  const Disk disk = triangulate_disk(s.radius, s.target_size, source);
  const auto n = static_cast<flow::GlobalIndex>(disk.nodes.size());

  flow::Mesh mesh;
  mesh.source = source;
  mesh.add_region("fluid");
  const int wall = mesh.add_patch("wall"), zmin = mesh.add_patch("zmin"),
            zmax = mesh.add_patch("zmax");
  for (int l = 0; l <= s.layers; ++l) {
    // z = l * (length / layers) rounded once per layer, so every node of a layer has the same z.
    const double z = s.length * l / s.layers;
    for (const auto& p : disk.nodes) mesh.nodes.emplace_back(p.x(), p.y(), z);
  }
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
  for (int l = 0; l < s.layers; ++l) {
    for (const auto& t : disk.triangles) {
      const std::array<flow::GlobalIndex, 6> prism{
          at(t[0], l), at(t[1], l), at(t[2], l), at(t[0], l + 1), at(t[1], l + 1), at(t[2], l + 1)};
      mesh.add_cell(flow::CellType::prism, prism);
    }
    for (const auto& [a, b] : boundary) {
      const std::array<flow::GlobalIndex, 4> quad{at(a, l), at(b, l), at(b, l + 1), at(a, l + 1)};
      mesh.add_face(quad, wall);
    }
  }
  for (const auto& t : disk.triangles) {
    const std::array<flow::GlobalIndex, 3> bottom{at(t[0], 0), at(t[2], 0), at(t[1], 0)};
    const std::array<flow::GlobalIndex, 3> top{at(t[0], s.layers), at(t[1], s.layers),
                                               at(t[2], s.layers)};
    mesh.add_face(bottom, zmin);
    mesh.add_face(top, zmax);
  }
  mesh.periodic.push_back({"zmin", "zmax", Eigen::Vector3d(0, 0, s.length)});
  return s.split ? split_prisms_to_tetrahedra(mesh) : mesh;
}

}  // namespace valsalva::io
