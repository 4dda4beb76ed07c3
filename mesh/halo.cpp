#include "mesh/halo.hpp"

#include <stdexcept>

namespace valsalva::mesh {

Halo::Halo(MPI_Comm comm, std::vector<Neighbour> neighbours)
    : comm_(comm), neighbours_(std::move(neighbours)) {
  send_buffers_.resize(neighbours_.size());
  recv_buffers_.resize(neighbours_.size());
}

void Halo::start(std::span<double> data, int components, HaloMode mode) {
  if (active_) throw std::logic_error("Halo::start called twice without finish");
  active_ = true;
  pending_ = data;
  components_ = components;
  mode_ = mode;
  requests_.assign(2 * neighbours_.size(), MPI_REQUEST_NULL);
  constexpr int tag = 7301;
  for (std::size_t i = 0; i < neighbours_.size(); ++i) {
    const auto& nb = neighbours_[i];
    // insert: owners send, ghosts receive; add: ghosts send, owners receive.
    const auto& outgoing = mode == HaloMode::insert ? nb.send : nb.recv;
    const auto& incoming = mode == HaloMode::insert ? nb.recv : nb.send;
    auto& out = send_buffers_[i];
    auto& in = recv_buffers_[i];
    out.resize(outgoing.size() * components);
    in.resize(incoming.size() * components);
    for (std::size_t k = 0; k < outgoing.size(); ++k)
      for (int c = 0; c < components; ++c)
        out[k * components + c] = data[static_cast<std::size_t>(outgoing[k]) * components + c];
    VALSALVA_MPI(MPI_Irecv(in.data(), static_cast<int>(in.size()), MPI_DOUBLE, nb.rank, tag, comm_,
                           &requests_[2 * i]));
    VALSALVA_MPI(MPI_Isend(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, nb.rank, tag,
                           comm_, &requests_[2 * i + 1]));
  }
}

void Halo::finish() {
  if (!active_) throw std::logic_error("Halo::finish without start");
  VALSALVA_MPI(
      MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE));
  const int nc = components_;
  for (std::size_t i = 0; i < neighbours_.size(); ++i) {
    const auto& nb = neighbours_[i];
    const auto& in = recv_buffers_[i];
    if (mode_ == HaloMode::insert) {
      for (std::size_t k = 0; k < nb.recv.size(); ++k)
        for (int c = 0; c < nc; ++c)
          pending_[static_cast<std::size_t>(nb.recv[k]) * nc + c] = in[k * nc + c];
    } else {
      for (std::size_t k = 0; k < nb.send.size(); ++k)
        for (int c = 0; c < nc; ++c)
          pending_[static_cast<std::size_t>(nb.send[k]) * nc + c] += in[k * nc + c];
    }
  }
  if (mode_ == HaloMode::add)
    for (const auto& nb : neighbours_)
      for (int g : nb.recv)
        for (int c = 0; c < nc; ++c) pending_[static_cast<std::size_t>(g) * nc + c] = 0.0;
  active_ = false;
}

}  // namespace valsalva::mesh
