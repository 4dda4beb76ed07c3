// The unstructured hybrid 3D mesh as read or generated: nodes, cells (tetrahedra, pyramids,
// prisms, hexahedra in Gmsh node order), tagged boundary faces and periodic links.
// Connectivity is stored CSR-style in flat arrays (no nested vectors).
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace valsalva::mesh {

using GlobalIndex = std::int64_t;

enum class CellType : std::uint8_t { tetra, pyramid, prism, hexa };
enum class FaceType : std::uint8_t { triangle, quad };

int node_count(CellType type);
const char* name(CellType type);

// Faces of a cell in its local node numbering, ordered so that the right-hand normal points out
// of the cell (for a positively oriented cell in Gmsh order).
std::span<const std::vector<int>> cell_faces(CellType type);
// Edges of a cell in its local node numbering (each once).
std::span<const std::pair<int, int>> cell_edges(CellType type);

// Periodic link: every node on patch `slave` sits at a node of patch `master` + translation.
struct PeriodicLink {
  std::string master;
  std::string slave;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

struct Mesh {
  std::vector<Eigen::Vector3d> nodes;

  std::vector<CellType> cell_types;
  std::vector<GlobalIndex> cell_offsets{0};  // size cells + 1
  std::vector<GlobalIndex> cell_nodes;
  std::vector<int> cell_regions;  // index into region_names
  std::vector<std::string> region_names;

  std::vector<GlobalIndex> face_offsets{0};  // boundary faces, size faces + 1
  std::vector<GlobalIndex> face_nodes;
  std::vector<int> face_patches;  // index into patch_names
  std::vector<std::string> patch_names;

  std::vector<PeriodicLink> periodic;
  std::string source = "<generated>";  // file name or generator, for error messages

  GlobalIndex num_nodes() const { return static_cast<GlobalIndex>(nodes.size()); }
  GlobalIndex num_cells() const { return static_cast<GlobalIndex>(cell_types.size()); }
  GlobalIndex num_faces() const { return static_cast<GlobalIndex>(face_patches.size()); }
  std::span<const GlobalIndex> cell(GlobalIndex c) const {
    return {cell_nodes.data() + cell_offsets[c], cell_nodes.data() + cell_offsets[c + 1]};
  }
  std::span<const GlobalIndex> face(GlobalIndex f) const {
    return {face_nodes.data() + face_offsets[f], face_nodes.data() + face_offsets[f + 1]};
  }
  int patch_index(const std::string& name) const;  // -1 when absent

  void add_cell(CellType type, std::span<const GlobalIndex> nodes_of_cell, int region = 0);
  void add_face(std::span<const GlobalIndex> nodes_of_face, int patch);
  int add_patch(const std::string& name);   // returns existing index if present
  int add_region(const std::string& name);  // returns existing index if present
};

}  // namespace valsalva::mesh
