// Extruded inlet/outlet pipe mesh; see extruded_pipe_generator.hpp.
#include "mesh/extruded_pipe_generator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/comm.hpp"
#include "mesh/prism_split.hpp"

namespace valsalva::mesh {

namespace {

// Rank 0's disk on every rank of `comm` (an exception on rank 0 is thrown on every rank).
Disk shared_disk(const ExtrudedPipeSpec& s, const std::string& source, MPI_Comm mpi_comm) {
  const core::Comm comm(mpi_comm);
  Disk disk;
  std::string error;
  if (comm.root()) try {
      disk = triangulate_disk(s.radius, s.target_size, s.grading, source);
    } catch (const std::exception& e) {
      error = e.what();
    }
  comm.broadcast(error);
  if (!error.empty()) throw std::invalid_argument(error);
  int sizes[2] = {static_cast<int>(disk.nodes.size()), static_cast<int>(disk.triangles.size())};
  comm.broadcast(std::span<int>(sizes));
  disk.nodes.resize(sizes[0]);
  disk.triangles.resize(sizes[1]);
  comm.broadcast(std::span<double>(disk.nodes.data()->data(), 2 * disk.nodes.size()));
  comm.broadcast(std::span<int>(disk.triangles.data()->data(), 3 * disk.triangles.size()));
  return disk;
}

}  // namespace

mesh::Mesh generate_extruded_pipe_mesh(const ExtrudedPipeSpec& s, MPI_Comm comm) {
  for (const auto& [name, value] :
       {std::pair{"radius", s.radius}, {"length", s.length}, {"target_size", s.target_size}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format(
          "generate_extruded_pipe_mesh: {} must be positive and finite, got {}", name, value));
  if (!(s.layer_height >= 0) || !std::isfinite(s.layer_height))
    throw std::invalid_argument(
        fmt::format("generate_extruded_pipe_mesh: layer_height must be >= 0 and finite, got {}",
                    s.layer_height));
  const double dz = s.layer_height > 0 ? s.layer_height : s.target_size;
  const int layers = std::max(1, static_cast<int>(std::lround(s.length / dz)));
  const std::string source = fmt::format(
      "extruded_pipe(radius={:g}, length={:g}, size={:g}, layers={}, wall={:g}/{:g}, "
      "rows={:g}*{:g}^k<={:g})",
      s.radius, s.length, s.target_size, layers, s.grading.wall_size, s.grading.wall_distance,
      s.grading.layer_first, s.grading.layer_ratio, s.grading.layer_thickness);
  const Disk disk = shared_disk(s, source, comm);
  std::vector<double> z;
  for (int l = 0; l <= layers; ++l) z.push_back(s.length * l / layers);
  return split_prisms_to_tetrahedra(extrude_disk(disk, z, "inlet", "outlet", source));
}

}  // namespace valsalva::mesh
