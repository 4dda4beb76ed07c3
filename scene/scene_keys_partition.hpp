// The parallel decomposition of a scene: the reader that goes with declare_partition_keys
// (scene/scene_keys_partition.cpp).
#pragma once

#include "mesh/local_mesh.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// partition.ghost_layers and partition.method.
mesh::PartitionOptions partition_options(const Scene& scene);

}  // namespace valsalva::scene
