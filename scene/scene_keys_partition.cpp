// Scene keys of the parallel decomposition (flow/ partitioning and halo exchange).
#include "scene/scene_keys_partition.hpp"

#include "scene/scene_keys.hpp"

namespace valsalva::scene {

void declare_partition_keys(Schema& s) {
  s.section("partition", "How the mesh nodes are distributed over MPI ranks.");
  s.integer("partition.ghost_layers")
      .def(2)
      .in_range(1, 4)
      .unit_of("-")
      .doc(
          "Depth of the ghost-node layers around each rank (the 4th-order scheme and IBM kernels "
          "need 2)");
  s.real("partition.ghost_distance")
      .def(0.0)
      .at_least(0.0)
      .unit_of("m")
      .doc(
          "Depth of the ghost region around each rank near the immersed structures, where "
          "partition.ghost_layers is not enough: every node within this distance of a rank's "
          "own nodes, inside the structures' box widened by a quarter of its size, is a ghost "
          "there. 0 = from the kernels: sqrt(3) r + h, r the support half-width at the largest "
          "h near the structures (floored at immersed.kernel_min_size); no effect without "
          "structures");
  s.choice("partition.method", mesh::partition_method_names())
      .def("metis")
      .unit_of("-")
      .doc("METIS k-way partition of the node graph, or contiguous blocks of global node numbers");
}

mesh::PartitionOptions partition_options(const Scene& scene) {
  mesh::PartitionOptions o;
  o.ghost_layers = scene.get<int>("partition.ghost_layers");
  o.method = mesh::parse_partition_method(scene.get<std::string>("partition.method"));
  return o;
}

}  // namespace valsalva::scene
