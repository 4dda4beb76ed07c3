#include "ibm/collective_error.hpp"

#include <stdexcept>

namespace valsalva::ibm {

void settle(const flow::Comm& comm, const std::string& local_error) {
  const int mine = local_error.empty() ? comm.size() : comm.rank();
  int first = 0;
  VALSALVA_MPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm.get()));
  if (first == comm.size()) return;
  int length = static_cast<int>(local_error.size());
  VALSALVA_MPI(MPI_Bcast(&length, 1, MPI_INT, first, comm.get()));
  std::string message = local_error;
  message.resize(static_cast<std::size_t>(length));
  VALSALVA_MPI(MPI_Bcast(message.data(), length, MPI_CHAR, first, comm.get()));
  if (first != comm.rank()) message += " (reported by rank " + std::to_string(first) + ")";
  throw std::runtime_error(message);
}

}  // namespace valsalva::ibm
