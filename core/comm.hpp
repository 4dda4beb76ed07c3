// The one MPI communicator wrapper: every MPI return code is checked, reductions are wrapped.
// MPI is always there; "serial" means one rank.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace valsalva::flow {

class MpiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws MpiError naming the call and its location when `code` is not MPI_SUCCESS.
void check_mpi(int code, const char* call, const char* file, int line);
#define VALSALVA_MPI(call) ::valsalva::flow::check_mpi((call), #call, __FILE__, __LINE__)

class Comm {
 public:
  explicit Comm(MPI_Comm comm = MPI_COMM_WORLD);
  MPI_Comm get() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  double sum(double x) const;
  double max(double x) const;
  double min(double x) const;
  std::int64_t sum(std::int64_t x) const;
  std::int64_t max(std::int64_t x) const;
  void barrier() const;

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace valsalva::flow
