#include "ibm/collective_error.hpp"

#include <stdexcept>

namespace valsalva::ibm {

void settle(const core::Comm& comm, const std::string& local_error) {
  const int first = static_cast<int>(comm.min(local_error.empty() ? comm.size() : comm.rank()));
  if (first == comm.size()) return;
  std::string message = local_error;
  comm.broadcast(message, first);
  if (first != comm.rank()) message += " (reported by rank " + std::to_string(first) + ")";
  throw std::runtime_error(message);
}

}  // namespace valsalva::ibm
