#pragma once
// The size of a partition's halo across ranks: what the run log prints and the scaling study
// (validation/bench/scaling_study.py) fits its communication model to.
#include <cstdint>

#include "mesh/local_mesh.hpp"

namespace valsalva::mesh {

struct HaloSize {
  std::int64_t owned_min = 0, owned_max = 0;  // owned nodes per rank
  std::int64_t ghosts_max = 0;                // ghost nodes on one rank
  std::int64_t neighbours_max = 0;            // ranks one rank exchanges with
  std::int64_t sent_max = 0;                  // values one rank sends in a scalar exchange
  std::int64_t deepest_layer = 0;             // deepest ghost layer on any rank
};

// Collective over local.comm; the same result on every rank.
HaloSize halo_size(const LocalMesh& local);

}  // namespace valsalva::mesh
