#include "core/comm.hpp"

#include <fmt/format.h>

#include <limits>

#include "core/check.hpp"

namespace valsalva::core {

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
bool Comm::any(bool x) const {
  return reduce(comm_, x ? 1 : 0, MPI_INT, MPI_LOR) != 0;
}
void Comm::barrier() const {
  VALSALVA_MPI(MPI_Barrier(comm_));
}

namespace {
// True on every rank when every rank passes the same length (a collective, debug builds only).
bool same_length_everywhere(MPI_Comm comm, std::size_t n) {
  const auto mine = static_cast<std::int64_t>(n);
  std::int64_t extremes[2] = {mine, -mine};
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, extremes, 2, MPI_INT64_T, MPI_MAX, comm));
  return extremes[0] == mine && -extremes[1] == mine;
}

void reduce_in_place(MPI_Comm comm, std::span<double> values, MPI_Op op) {
  VALSALVA_CHECK(values.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                 "more values than one MPI call takes");
  VALSALVA_DEBUG_CHECK(same_length_everywhere(comm, values.size()),
                       "ranks reduce arrays of different lengths");
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()),
                             MPI_DOUBLE, op, comm));
}

// Counts and offsets of every rank's piece, on every rank.
std::vector<int> piece_counts(MPI_Comm comm, int size, std::size_t mine) {
  VALSALVA_CHECK(mine <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                 "a piece larger than one MPI call takes");
  const int n = static_cast<int>(mine);
  std::vector<int> counts(size);
  VALSALVA_MPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  return counts;
}

std::vector<int> offsets_of(const std::vector<int>& counts) {
  std::vector<int> offsets(counts.size(), 0);
  std::int64_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = static_cast<int>(total);
    total += counts[r];
    VALSALVA_CHECK(total <= std::numeric_limits<int>::max(), "gathered pieces exceed one MPI call");
  }
  return offsets;
}
}  // namespace

void Comm::sum_in_place(std::span<double> values) const {
  reduce_in_place(comm_, values, MPI_SUM);
}
void Comm::max_in_place(std::span<double> values) const {
  reduce_in_place(comm_, values, MPI_MAX);
}
void Comm::min_in_place(std::span<double> values) const {
  reduce_in_place(comm_, values, MPI_MIN);
}

std::vector<double> Comm::gather_to_root(std::span<const double> mine) const {
  const auto counts = piece_counts(comm_, size_, mine.size());
  const auto offsets = offsets_of(counts);
  std::vector<double> all(root() ? static_cast<std::size_t>(offsets.back() + counts.back()) : 0);
  VALSALVA_MPI(MPI_Gatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                           counts.data(), offsets.data(), MPI_DOUBLE, 0, comm_));
  return all;
}

std::vector<std::int64_t> Comm::all_gather(std::span<const std::int64_t> mine) const {
  const auto counts = piece_counts(comm_, size_, mine.size());
  const auto offsets = offsets_of(counts);
  std::vector<std::int64_t> all(static_cast<std::size_t>(offsets.back() + counts.back()));
  VALSALVA_MPI(MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_INT64_T, all.data(),
                              counts.data(), offsets.data(), MPI_INT64_T, comm_));
  return all;
}

void Comm::broadcast(std::span<double> values, int root) const {
  VALSALVA_MPI(MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, root, comm_));
}
void Comm::broadcast(std::span<int> values, int root) const {
  VALSALVA_MPI(MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_INT, root, comm_));
}
void Comm::broadcast(std::string& text, int root) const {
  int length = static_cast<int>(text.size());
  broadcast(length, root);
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) VALSALVA_MPI(MPI_Bcast(text.data(), length, MPI_CHAR, root, comm_));
}
void Comm::broadcast(std::vector<double>& values, int root) const {
  int length = static_cast<int>(values.size());
  broadcast(length, root);
  values.resize(static_cast<std::size_t>(length));
  broadcast(std::span<double>(values), root);
}

}  // namespace valsalva::core
