#include "core/comm.hpp"

#include <fmt/format.h>

namespace valsalva::flow {

void check_mpi(int code, const char* call, const char* file, int line) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw MpiError(fmt::format("{}:{}: {} failed: {}", file, line, call, std::string(text, length)));
}

Comm::Comm(MPI_Comm comm) : comm_(comm) {
  VALSALVA_MPI(MPI_Comm_rank(comm_, &rank_));
  VALSALVA_MPI(MPI_Comm_size(comm_, &size_));
}

namespace {
template <class T>
T reduce(MPI_Comm comm, T x, MPI_Datatype type, MPI_Op op) {
  T out{};
  VALSALVA_MPI(MPI_Allreduce(&x, &out, 1, type, op, comm));
  return out;
}
}  // namespace

double Comm::sum(double x) const {
  return reduce(comm_, x, MPI_DOUBLE, MPI_SUM);
}
double Comm::max(double x) const {
  return reduce(comm_, x, MPI_DOUBLE, MPI_MAX);
}
double Comm::min(double x) const {
  return reduce(comm_, x, MPI_DOUBLE, MPI_MIN);
}
std::int64_t Comm::sum(std::int64_t x) const {
  return reduce(comm_, x, MPI_INT64_T, MPI_SUM);
}
std::int64_t Comm::max(std::int64_t x) const {
  return reduce(comm_, x, MPI_INT64_T, MPI_MAX);
}
void Comm::barrier() const {
  VALSALVA_MPI(MPI_Barrier(comm_));
}

}  // namespace valsalva::flow
