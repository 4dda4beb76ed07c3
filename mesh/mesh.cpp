#include "mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace valsalva::mesh {

int node_count(CellType type) {
  switch (type) {
    case CellType::tetra:
      return 4;
    case CellType::pyramid:
      return 5;
    case CellType::prism:
      return 6;
    case CellType::hexa:
      return 8;
  }
  throw std::logic_error("unknown cell type");
}

const char* name(CellType type) {
  switch (type) {
    case CellType::tetra:
      return "tetrahedron";
    case CellType::pyramid:
      return "pyramid";
    case CellType::prism:
      return "prism";
    case CellType::hexa:
      return "hexahedron";
  }
  return "?";
}

std::span<const std::vector<int>> cell_faces(CellType type) {
  static const std::array<std::vector<int>, 4> tet{{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  static const std::array<std::vector<int>, 5> pyr{
      {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};
  static const std::array<std::vector<int>, 5> pri{
      {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}};
  static const std::array<std::vector<int>, 6> hex{
      {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  switch (type) {
    case CellType::tetra:
      return tet;
    case CellType::pyramid:
      return pyr;
    case CellType::prism:
      return pri;
    case CellType::hexa:
      return hex;
  }
  throw std::logic_error("unknown cell type");
}

std::span<const std::pair<int, int>> cell_edges(CellType type) {
  // Derived once from the faces: every face side (a, b) is an edge, kept once.
  static const auto table = [] {
    std::array<std::vector<std::pair<int, int>>, 4> edges;
    for (CellType t : {CellType::tetra, CellType::pyramid, CellType::prism, CellType::hexa}) {
      auto& list = edges[static_cast<int>(t)];
      for (const auto& f : cell_faces(t))
        for (std::size_t i = 0; i < f.size(); ++i) {
          const int a = std::min(f[i], f[(i + 1) % f.size()]);
          const int b = std::max(f[i], f[(i + 1) % f.size()]);
          if (std::find(list.begin(), list.end(), std::pair{a, b}) == list.end())
            list.emplace_back(a, b);
        }
    }
    return edges;
  }();
  return table[static_cast<int>(type)];
}

int Mesh::patch_index(const std::string& patch) const {
  auto it = std::find(patch_names.begin(), patch_names.end(), patch);
  return it == patch_names.end() ? -1 : static_cast<int>(it - patch_names.begin());
}

void Mesh::add_cell(CellType type, std::span<const GlobalIndex> nodes_of_cell, int region) {
  if (static_cast<int>(nodes_of_cell.size()) != node_count(type))
    throw std::logic_error("add_cell: node count does not match the cell type");
  cell_types.push_back(type);
  cell_nodes.insert(cell_nodes.end(), nodes_of_cell.begin(), nodes_of_cell.end());
  cell_offsets.push_back(static_cast<GlobalIndex>(cell_nodes.size()));
  cell_regions.push_back(region);
}

void Mesh::add_face(std::span<const GlobalIndex> nodes_of_face, int patch) {
  face_nodes.insert(face_nodes.end(), nodes_of_face.begin(), nodes_of_face.end());
  face_offsets.push_back(static_cast<GlobalIndex>(face_nodes.size()));
  face_patches.push_back(patch);
}

int Mesh::add_patch(const std::string& patch) {
  int i = patch_index(patch);
  if (i >= 0) return i;
  patch_names.push_back(patch);
  return static_cast<int>(patch_names.size()) - 1;
}

int Mesh::add_region(const std::string& region) {
  auto it = std::find(region_names.begin(), region_names.end(), region);
  if (it != region_names.end()) return static_cast<int>(it - region_names.begin());
  region_names.push_back(region);
  return static_cast<int>(region_names.size()) - 1;
}

}  // namespace valsalva::mesh
