// Nodal fields of a distributed run to HDF5 + XDMF on the mesh as read (periodic images keep
// their own nodes, so ParaView shows the true geometry). Each rank writes the mesh nodes whose
// dual node it owns and the cells whose first node it owns.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "io/xdmf_writer.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::io {

class FieldOutput {
 public:
  FieldOutput(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
              const mesh::LocalMesh& local, const std::filesystem::path& dir,
              const std::string& basename);

  // Fields are local arrays (owned nodes first, as in LocalMesh); only owned values are read.
  struct Scalar {
    std::string name;
    const std::vector<double>* values;
  };
  struct Vector {
    std::string name;
    const std::vector<Eigen::Vector3d>* values;
  };
  std::filesystem::path write(double time, const std::vector<Scalar>& scalars,
                              const std::vector<Vector>& vectors = {});
  std::filesystem::path xmf_file() const { return writer_->xmf_file(); }

 private:
  std::vector<int> local_of_output_node_;  // owned mesh node -> local dual node
  std::unique_ptr<XdmfWriter> writer_;
  std::vector<std::vector<double>> scalar_buffers_;
  std::vector<std::vector<Eigen::Vector3d>> vector_buffers_;
};

}  // namespace valsalva::io
