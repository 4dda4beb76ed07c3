#pragma once
// The ghost region the immersed kernels need. A marker's support is a box of half-width
// r = support_radius(kernel, max(h, immersed.kernel_min_size)) around it, evaluated by the rank
// owning its nearest node, so that rank must see every node within sqrt(3) r + h of its owned
// nodes wherever markers go. Counted in layers this depth depends on the local cell size (the
// small cells around a frame's posts put 4 and more layers inside one kernel), so it is given
// to the partition as a distance, within a box around the structures (elsewhere the flow's
// ghost_layers suffice).
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "scene/scene_keys_structure.hpp"

namespace valsalva::run {

// The ghost region for the structures of `setup` (none without structures). The box is the
// structures' bounding box widened by a quarter of its largest side (room for their motion) and by
// the distance; `distance` > 0 replaces the kernel-derived distance (the scene key
// partition.ghost_distance).
mesh::GhostRegion marker_ghost_region(const scene::ImmersedSetup& setup,
                                      const mesh::DualMetrics& metrics, double distance);

}  // namespace valsalva::run
