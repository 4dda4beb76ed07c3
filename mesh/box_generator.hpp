// Built-in structured box meshes: hexahedra, or the same grid split into tetrahedra (Kuhn's
// 6-tetrahedra split, conforming across cells), prisms, pyramids (6 per hexahedron around a
// centre node) or a conforming mix of all four; optional random node perturbation and periodic
// pairs. Patches: xmin, xmax, ymin, ymax, zmin, zmax; region "fluid".
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// The cells of a box (the scene key mesh.box.cell_type): hexahedra, each hexahedron split into
// tetrahedra, prisms or pyramids, or slabs of all four (mixed).
enum class BoxCellType { hexa, tetra, prism, pyramid, mixed };

// The scene names, in the order of the enum: "hexa", "tetra", "prism", "pyramid", "mixed".
const std::vector<std::string>& box_cell_type_names();
std::string to_string(BoxCellType type);
// std::invalid_argument naming the value and the accepted names for an unknown name.
BoxCellType parse_box_cell_type(std::string_view name);

struct BoxSpec {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d length = Eigen::Vector3d::Ones();
  std::array<int, 3> cells{8, 8, 8};
  BoxCellType cell_type = BoxCellType::hexa;
  double perturbation = 0.0;  // amplitude per component, as a fraction of the cell size
  std::uint64_t seed = 1;
  std::array<bool, 3> periodic{false, false, false};
};

// Throws std::invalid_argument naming the bad parameter.
mesh::Mesh generate_box(const BoxSpec& spec);

}  // namespace valsalva::mesh
