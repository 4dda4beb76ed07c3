#include "analysis/statistics_files.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "core/numeric_table.hpp"
#include "io/hdf5_file.hpp"
#include "io/xdmf_writer.hpp"

namespace valsalva::analysis {

mesh::Mesh read_statistics_mesh(const std::filesystem::path& file) {
  const io::h5::File h5(file, io::h5::Mode::read);
  const auto xyz = h5.read_all<double>("coordinates");
  const auto topo = h5.read_all<std::int64_t>("topology");
  mesh::Mesh mesh;
  mesh.source = file.string();
  if (xyz.size() % 3 != 0)
    throw std::runtime_error(fmt::format("'{}': 'coordinates' holds {} values, not 3 per node",
                                         file.string(), xyz.size()));
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    mesh.nodes.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  const auto num_nodes = static_cast<std::int64_t>(mesh.nodes.size());
  for (std::size_t i = 0; i < topo.size();) {
    // XDMF Mixed-topology codes 6..9 (xdmf_writer.hpp) are tetra, pyramid, prism, hexa.
    constexpr mesh::CellType types[] = {mesh::CellType::tetra, mesh::CellType::pyramid,
                                        mesh::CellType::prism, mesh::CellType::hexa};
    if (topo[i] < 6 || topo[i] > 9)
      throw std::runtime_error(
          fmt::format("'{}': topology entry {} has XDMF cell code {}", file.string(), i, topo[i]));
    const mesh::CellType type = types[topo[i] - 6];
    const int n = mesh::node_count(type);
    if (i + 1 + n > topo.size())
      throw std::runtime_error(
          fmt::format("'{}': topology ends inside the cell at entry {}", file.string(), i));
    std::vector<mesh::GlobalIndex> nodes(topo.begin() + i + 1, topo.begin() + i + 1 + n);
    for (auto node : nodes)
      if (node < 0 || node >= num_nodes)
        throw std::runtime_error(
            fmt::format("'{}': topology entry {} refers to node {}, but the file has {} nodes",
                        file.string(), i, node, num_nodes));
    if (type == mesh::CellType::prism) std::swap(nodes[1], nodes[2]), std::swap(nodes[4], nodes[5]);
    mesh.add_cell(type, nodes);
    i += 1 + n;
  }
  return mesh;
}

std::vector<double> read_phase_times(const std::filesystem::path& file) {
  return core::read_numeric_table(file, core::TableHeader::required).column("phase_time");
}

SimulationStatistics read_statistics_bin(const std::filesystem::path& file, const mesh::Mesh& mesh,
                                         const std::filesystem::path& mesh_file) {
  const auto nodes = static_cast<std::size_t>(mesh.num_nodes());
  auto field = [&](const char* name, std::size_t per_node) {
    auto v = io::read_nodal_field(file, name);
    if (v.size() != per_node * nodes)
      throw std::runtime_error(fmt::format(
          "compare-piv: '{}' dataset '{}' has {} values ({} per node: {} nodes), but the "
          "statistics mesh '{}' has {} nodes: the bin and the mesh come from different runs",
          file.string(), name, v.size(), per_node, v.size() / per_node, mesh_file.string(), nodes));
    return v;
  };
  SimulationStatistics s;
  s.mean_velocity = field("mean_velocity", 3);
  s.rms_velocity = field("rms_velocity", 3);
  s.reynolds_uv = field("reynolds_uv", 1);
  s.reynolds_uw = field("reynolds_uw", 1);
  s.reynolds_vw = field("reynolds_vw", 1);
  return s;
}

}  // namespace valsalva::analysis
