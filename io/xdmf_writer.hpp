// Parallel output of an unstructured hybrid mesh and nodal fields for ParaView: HDF5 heavy data
// written by every rank (collective hyperslabs, rows = global node ids, no gather on rank 0)
// plus one XDMF 3 temporal collection <basename>.xmf rewritten by rank 0 after each step.
//
// Files in `dir`:
//   <basename>_mesh.h5    /coordinates [N x 3], /topology (XDMF Mixed, int64), /partition [cells]
//   <basename>_NNNNNN.h5  one dataset per field ([N] or [N x 3]) and the attribute "time"
//   (both .h5 files carry the attribute "global_nodes" = N)
//   <basename>.xmf        the time series; ParaView opens it with its XDMF3 reader
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace valsalva::io {

struct ScalarField {
  std::string name;
  std::span<const double> values;  // one per owned node, in owned_node_global_ids order
};

struct VectorField {
  std::string name;
  std::span<const Eigen::Vector3d> values;
};

// Cell types of a surface grid, after the four mesh::CellType values.
constexpr std::uint8_t kTriangleCell = 4, kQuadCell = 5;

class XdmfWriter {
 public:
  // Collective. Writes <basename>_mesh.h5. Cells are the ones this rank owns: cell_types holds
  // mesh::CellType values (0 tetra, 1 pyramid, 2 prism, 3 hexa) with nodes in Gmsh order, or
  // surface cells (4 triangle, 5 quad) for a boundary's surface,
  // cell_offsets has cells + 1 entries into cell_nodes_global (global node ids).
  XdmfWriter(MPI_Comm comm, std::filesystem::path dir, std::string basename,
             std::int64_t global_nodes, std::span<const std::int64_t> owned_node_global_ids,
             std::span<const Eigen::Vector3d> owned_node_coords,
             std::span<const std::uint8_t> cell_types, std::span<const std::int64_t> cell_offsets,
             std::span<const std::int64_t> cell_nodes_global);

  // Collective. Writes <basename>_NNNNNN.h5 (NNNNNN = number of steps written before) and
  // rewrites <basename>.xmf; returns the path of the step file. Field names: [A-Za-z0-9_.-]+.
  std::filesystem::path write_step(double time, std::span<const ScalarField> scalars,
                                   std::span<const VectorField> vectors = {});

  std::filesystem::path mesh_file() const { return dir_ / (basename_ + "_mesh.h5"); }
  std::filesystem::path xmf_file() const { return dir_ / (basename_ + ".xmf"); }
  int steps_written() const { return static_cast<int>(steps_.size()); }
  std::int64_t global_cells() const { return global_cells_; }

 private:
  struct Step {
    double time;
    std::string file;                                 // name relative to dir_
    std::vector<std::pair<std::string, int>> fields;  // name, components (1 or 3)
  };
  void write_xmf() const;

  MPI_Comm comm_;
  int rank_ = 0;
  std::filesystem::path dir_;
  std::string basename_;
  std::int64_t global_nodes_;
  std::vector<std::int64_t> owned_ids_;
  std::int64_t global_cells_ = 0;
  std::int64_t topology_size_ = 0;
  std::vector<Step> steps_;  // kept on every rank, used by rank 0
};

// Reads nodal field `name` (a step field, or "coordinates" of the mesh file) of this process:
// row-major values, rows = global node ids, 1 or 3 per node.
std::vector<double> read_nodal_field(const std::filesystem::path& file, const std::string& name);

// Collective: only the rows `global_ids` (e.g. the nodes of a new partition at restart).
std::vector<double> read_nodal_field(MPI_Comm comm, const std::filesystem::path& file,
                                     const std::string& name,
                                     std::span<const std::int64_t> global_ids);

}  // namespace valsalva::io
