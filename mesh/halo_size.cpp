#include "mesh/halo_size.hpp"

#include <algorithm>

namespace valsalva::mesh {

HaloSize halo_size(const LocalMesh& local) {
  const auto& comm = local.comm;
  std::int64_t sent = 0;
  for (const auto& n : local.halo.neighbours()) sent += static_cast<std::int64_t>(n.send.size());
  const std::int64_t owned = local.num_owned;
  HaloSize size;
  size.owned_min = -comm.max(-owned);
  size.owned_max = comm.max(owned);
  size.ghosts_max = comm.max(static_cast<std::int64_t>(local.num_local() - local.num_owned));
  size.neighbours_max = comm.max(static_cast<std::int64_t>(local.halo.neighbours().size()));
  size.sent_max = comm.max(sent);
  std::int64_t deepest = 0;
  for (int layer : local.ghost_layer) deepest = std::max<std::int64_t>(deepest, layer);
  size.deepest_layer = comm.max(deepest);
  return size;
}

}  // namespace valsalva::mesh
