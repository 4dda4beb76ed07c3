// Gathering sampled values on rank 0; see gather_to_root.hpp.
#include "validation/gather_to_root.hpp"

#include "core/comm.hpp"

namespace valsalva::validation {

std::vector<double> gather_to_root(const std::vector<double>& mine, MPI_Comm comm) {
  int size = 0, rank = 0;
  VALSALVA_MPI(MPI_Comm_size(comm, &size));
  VALSALVA_MPI(MPI_Comm_rank(comm, &rank));
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(size), offsets(size, 0);
  VALSALVA_MPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(rank == 0 ? offsets.back() + counts.back() : 0);
  VALSALVA_MPI(MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                           MPI_DOUBLE, 0, comm));
  return all;
}

std::vector<double> velocity_by_dual_node(const flow::LocalMesh& local, const flow::VectorField& u,
                                          std::int64_t dual_nodes) {
  std::vector<double> all(3 * static_cast<std::size_t>(dual_nodes), 0.0);
  for (int j = 0; j < local.num_owned; ++j)
    for (int c = 0; c < 3; ++c) all[3 * local.dual_node[j] + c] = u[j][c];
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE,
                             MPI_SUM, local.comm.get()));
  return all;
}

std::vector<double> scalar_by_dual_node(const flow::LocalMesh& local,
                                        const std::vector<double>& field, std::int64_t dual_nodes) {
  std::vector<double> all(static_cast<std::size_t>(dual_nodes), 0.0);
  for (int j = 0; j < local.num_owned; ++j) all[local.dual_node[j]] = field[j];
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_DOUBLE,
                             MPI_SUM, local.comm.get()));
  return all;
}

}  // namespace valsalva::validation
