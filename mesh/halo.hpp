// Halo exchange between ranks, in one place. Local node arrays hold owned nodes first, then
// ghost copies. "insert" copies owned values to the ghost copies on other ranks; "add" sends
// contributions made on ghost copies (immersed-boundary spreading) back to their owners, which
// add them, and zeroes the ghost copies. start/finish let computation overlap communication.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <vector>

#include "core/comm.hpp"

namespace valsalva::mesh {

enum class HaloMode { insert, add };

class Halo {
 public:
  struct Neighbour {
    int rank = 0;
    std::vector<int> send;  // local indices of owned nodes whose values the neighbour needs
    std::vector<int> recv;  // local indices of ghost copies of the neighbour's nodes
  };

  Halo() = default;
  Halo(MPI_Comm comm, std::vector<Neighbour> neighbours);

  // `data` holds `components` doubles per local node (node-major).
  void start(std::span<double> data, int components, HaloMode mode);
  void finish();
  void exchange(std::span<double> data, int components, HaloMode mode) {
    start(data, components, mode);
    finish();
  }
  void exchange(std::vector<double>& v, HaloMode mode = HaloMode::insert) {
    exchange(std::span<double>(v), 1, mode);
  }
  void exchange(std::vector<Eigen::Vector3d>& v, HaloMode mode = HaloMode::insert) {
    exchange(std::span<double>(v.data()->data(), 3 * v.size()), 3, mode);
  }

  const std::vector<Neighbour>& neighbours() const { return neighbours_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::vector<Neighbour> neighbours_;
  std::vector<std::vector<double>> send_buffers_, recv_buffers_;
  std::vector<MPI_Request> requests_;
  std::span<double> pending_;
  int components_ = 1;
  HaloMode mode_ = HaloMode::insert;
  bool active_ = false;
};

}  // namespace valsalva::mesh
