// The one MPI communicator wrapper: every MPI return code is checked, reductions are wrapped.
// MPI is always there; "serial" means one rank.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace valsalva::core {

class MpiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws MpiError naming the call and its location when `code` is not MPI_SUCCESS.
void check_mpi(int code, const char* call, const char* file, int line);
#define VALSALVA_MPI(call) ::valsalva::core::check_mpi((call), #call, __FILE__, __LINE__)

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
  // True on every rank when `x` is true on any rank.
  bool any(bool x) const;
  void barrier() const;

  // Element-wise reductions in place, the same result on every rank (every rank passes the same
  // length).
  void sum_in_place(std::span<double> values) const;
  void max_in_place(std::span<double> values) const;
  void min_in_place(std::span<double> values) const;

  // Every rank's `mine` concatenated in rank order: on rank 0 only (gather_to_root; the others
  // get an empty vector) or on every rank (all_gather). Lengths may differ between ranks.
  std::vector<double> gather_to_root(std::span<const double> mine) const;
  std::vector<std::int64_t> all_gather(std::span<const std::int64_t> mine) const;

  // `values` of rank `root` copied to every rank (same length on every rank); a string or a
  // vector of any length, resized on the receivers.
  void broadcast(std::span<double> values, int root = 0) const;
  void broadcast(std::span<int> values, int root = 0) const;
  void broadcast(double& value, int root = 0) const {
    broadcast(std::span<double>(&value, 1), root);
  }
  void broadcast(int& value, int root = 0) const { broadcast(std::span<int>(&value, 1), root); }
  void broadcast(std::string& text, int root = 0) const;
  void broadcast(std::vector<double>& values, int root = 0) const;

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace valsalva::core
