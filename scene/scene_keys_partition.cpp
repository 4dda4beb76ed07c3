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
