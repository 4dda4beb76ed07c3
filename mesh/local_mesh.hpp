// The part of the mesh one rank works on: its owned dual nodes (a contiguous range of the global
// numbering, so hypre's IJ interface can use it directly), then ghost copies in layers, with
// the median-dual metrics restricted to them and the halo that keeps ghosts up to date.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/comm.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/halo.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// How the dual nodes are split over the ranks (the scene key partition.method): METIS k-way on
// the node graph, or contiguous blocks of global node numbers.
enum class PartitionMethod { metis, block };

// The scene names, in the order of the enum: "metis", "block".
const std::vector<std::string>& partition_method_names();
std::string to_string(PartitionMethod method);
// std::invalid_argument naming the value and the accepted names for an unknown name.
PartitionMethod parse_partition_method(std::string_view name);

struct PartitionOptions {
  int ghost_layers = 2;  // the 4th-order scheme and the IBM kernels need >= 2
  PartitionMethod method = PartitionMethod::metis;
};

// Ghosts beyond PartitionOptions::ghost_layers: nodes inside `box` get more layers until every
// node there within `distance` of an owned node is local (0: none). The immersed kernels'
// supports need this depth in metres, not in layers: small cells near a rigid frame put many
// layers inside one kernel (run/immersed_ghosts.hpp sets it).
struct GhostRegion {
  double distance = 0;
  Eigen::AlignedBox3d box;
};

struct LocalMesh {
  core::Comm comm;
  int num_owned = 0;                   // local nodes [0, num_owned) are owned
  std::vector<GlobalIndex> global_id;  // hypre numbering; owned ids are contiguous
  GlobalIndex first_owned = 0;         // global id of local node 0
  GlobalIndex global_nodes = 0;
  std::vector<int> ghost_layer;  // 0 for owned nodes
  // 1 for ghost nodes with a mesh neighbour that is not local: the edge of what this rank sees.
  std::vector<char> frontier;
  std::vector<GlobalIndex> dual_node;  // index in the replicated DualMetrics

  std::vector<Eigen::Vector3d> position;
  std::vector<double> volume;
  std::vector<double> h;
  std::vector<Eigen::Vector3d> first_moment;
  std::vector<SymTensor> second_moment;
  std::vector<Eigen::Matrix3d> gradient_correction;

  // Edges with both ends local; the first `num_owned_edges` touch at least one owned node,
  // which is all an owned node's fluxes need.
  std::vector<std::array<int, 2>> edges;
  std::vector<Eigen::Vector3d> edge_normal;
  std::vector<Eigen::Vector3d> edge_vector;
  int num_owned_edges = 0;
  // Index of each local edge in DualMetrics::edges, and whether the local orientation (lower to
  // higher local index) is the reverse of the global one (lower to higher dual node): edge data
  // such as the face mass flux is stored by global edge in checkpoints.
  std::vector<GlobalIndex> global_edge;
  std::vector<char> edge_flipped;

  struct BoundaryFace {
    int node = 0;
    int patch = 0;
    Eigen::Vector3d area{0, 0, 0};
  };
  std::vector<BoundaryFace> boundary;  // for every local node
  std::vector<std::string> patch_names;

  Halo halo;

  int num_local() const { return static_cast<int>(global_id.size()); }
};

// Partitions the dual-node graph (METIS k-way on rank 0, broadcast) and builds this rank's part.
LocalMesh distribute(const Mesh& mesh, const DualMetrics& metrics, MPI_Comm comm,
                     const PartitionOptions& options = {}, const GhostRegion& extra = {});

// Owner rank of every dual node (same on all ranks); exposed for tests and output.
std::vector<int> partition_nodes(const DualMetrics& metrics, const core::Comm& comm,
                                 PartitionMethod method);

}  // namespace valsalva::mesh
