// Extruded periodic pipe mesh; see periodic_pipe_generator.hpp.
#include "mesh/periodic_pipe_generator.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "mesh/extruded_disk.hpp"
#include "mesh/prism_split.hpp"

namespace valsalva::mesh {

mesh::Mesh generate_periodic_pipe_mesh(const PeriodicPipeSpec& s) {
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
  const Disk disk = triangulate_disk(s.radius, s.target_size, DiskWallGrading{}, source);
  // z = l * (length / layers) rounded once per layer, so every node of a layer has the same z.
  std::vector<double> z;
  for (int l = 0; l <= s.layers; ++l) z.push_back(s.length * l / s.layers);
  auto mesh = extrude_disk(disk, z, "zmin", "zmax", source);
  mesh.periodic.push_back({"zmin", "zmax", Eigen::Vector3d(0, 0, s.length)});
  return s.split ? split_prisms_to_tetrahedra(mesh) : mesh;
}

}  // namespace valsalva::mesh
