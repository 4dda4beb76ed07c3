// Gathering sampled values on rank 0; see gather_to_root.hpp.
#include "validation/gather_to_root.hpp"

#include "core/comm.hpp"

namespace valsalva::validation {

std::vector<double> gather_to_root(const std::vector<double>& mine, MPI_Comm comm) {
  return core::Comm(comm).gather_to_root(mine);
}

std::vector<double> velocity_by_dual_node(const mesh::LocalMesh& local, const flow::VectorField& u,
                                          std::int64_t dual_nodes) {
  std::vector<double> all(3 * static_cast<std::size_t>(dual_nodes), 0.0);
  for (int j = 0; j < local.num_owned; ++j)
    for (int c = 0; c < 3; ++c) all[3 * local.dual_node[j] + c] = u[j][c];
  local.comm.sum_in_place(all);
  return all;
}

std::vector<double> scalar_by_dual_node(const mesh::LocalMesh& local,
                                        const std::vector<double>& field, std::int64_t dual_nodes) {
  std::vector<double> all(static_cast<std::size_t>(dual_nodes), 0.0);
  for (int j = 0; j < local.num_owned; ++j) all[local.dual_node[j]] = field[j];
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE,
                             MPI_SUM, local.comm.get()));
  return all;
}

}  // namespace valsalva::validation
