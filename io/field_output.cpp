#include "io/field_output.hpp"

#include <unordered_map>

namespace valsalva::io {

FieldOutput::FieldOutput(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                         const mesh::LocalMesh& local, const std::filesystem::path& dir,
                         const std::string& basename) {
  std::unordered_map<mesh::GlobalIndex, int> local_of_dual;
  for (int i = 0; i < local.num_owned; ++i) local_of_dual[local.dual_node[i]] = i;
  std::vector<std::int64_t> ids;
  std::vector<Eigen::Vector3d> coords;
  for (mesh::GlobalIndex n = 0; n < mesh.num_nodes(); ++n) {
    auto it = local_of_dual.find(metrics.dual_of_mesh_node[n]);
    if (it == local_of_dual.end()) continue;
    ids.push_back(n);
    coords.push_back(mesh.nodes[n]);
    local_of_output_node_.push_back(it->second);
  }
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> offsets{0}, nodes;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto cell = mesh.cell(c);
    if (!local_of_dual.contains(metrics.dual_of_mesh_node[cell[0]])) continue;
    types.push_back(static_cast<std::uint8_t>(mesh.cell_types[c]));
    nodes.insert(nodes.end(), cell.begin(), cell.end());
    offsets.push_back(static_cast<std::int64_t>(nodes.size()));
  }
  writer_ = std::make_unique<XdmfWriter>(local.comm.get(), dir, basename, mesh.num_nodes(), ids,
                                         coords, types, offsets, nodes);
}

std::filesystem::path FieldOutput::write(double time, const std::vector<Scalar>& scalars,
                                         const std::vector<Vector>& vectors) {
  scalar_buffers_.resize(scalars.size());
  vector_buffers_.resize(vectors.size());
  std::vector<ScalarField> s;
  std::vector<VectorField> v;
  for (std::size_t f = 0; f < scalars.size(); ++f) {
    auto& buf = scalar_buffers_[f];
    buf.resize(local_of_output_node_.size());
    for (std::size_t i = 0; i < buf.size(); ++i)
      buf[i] = (*scalars[f].values)[local_of_output_node_[i]];
    s.push_back({scalars[f].name, buf});
  }
  for (std::size_t f = 0; f < vectors.size(); ++f) {
    auto& buf = vector_buffers_[f];
    buf.resize(local_of_output_node_.size());
    for (std::size_t i = 0; i < buf.size(); ++i)
      buf[i] = (*vectors[f].values)[local_of_output_node_[i]];
    v.push_back({vectors[f].name, buf});
  }
  return writer_->write_step(time, s, v);
}

}  // namespace valsalva::io
