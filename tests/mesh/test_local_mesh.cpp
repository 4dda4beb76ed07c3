// Distributed mesh at 1, 2 and 3 ranks: owned dual volumes add up to the mesh volume, owned
// dual volumes close, Green-Gauss gradients of linear fields are exact at owned nodes, halo
// insert and add round-trip, and global sums agree with the replicated metrics.
#include <doctest/doctest.h>

#include <cmath>

#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/metric_identities.hpp"

using namespace valsalva;

namespace {

mesh::Mesh test_mesh(const std::string& type, bool periodic) {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::parse_box_cell_type(type);
  spec.cells = {8, 6, 5};
  spec.length = Eigen::Vector3d(1.0, 0.6, 0.5);
  spec.perturbation = type == "tetra" ? 0.2 : 0.0;
  spec.periodic = {false, periodic, periodic};
  return mesh::generate_box(spec);
}

}  // namespace

TEST_CASE("distributed dual metrics and halo") {
  for (std::string type : {"tetra", "hexa", "mixed"}) {
    for (bool periodic : {false, true}) {
      CAPTURE(type);
      CAPTURE(periodic);
      const auto mesh = test_mesh(type, periodic);
      const auto metrics = mesh::compute_dual_metrics(mesh);
      auto local =
          mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
      const auto& comm = local.comm;

      // Ownership covers every node exactly once.
      CHECK(comm.sum(static_cast<std::int64_t>(local.num_owned)) == metrics.num_nodes());

      const auto id = mesh::measure_metric_identities(local, mesh::mesh_volume(mesh),
                                                      Eigen::Vector3d(0.7, -1.9, 0.35));
      CHECK(id.volume_error < 1e-12);
      CHECK(id.closure_error < 1e-12);
      CHECK(id.gradient_error < 1e-10);

      // Halo insert: ghosts receive their owner's value (a function of the global id).
      std::vector<Eigen::Vector3d> field(local.num_local(), Eigen::Vector3d::Constant(-1.0));
      for (int i = 0; i < local.num_owned; ++i)
        field[i] =
            Eigen::Vector3d(local.global_id[i], 2.0 * local.global_id[i], local.position[i].x());
      local.halo.exchange(field, mesh::HaloMode::insert);
      int wrong = 0;
      for (int i = local.num_owned; i < local.num_local(); ++i)
        wrong += field[i] != Eigen::Vector3d(local.global_id[i], 2.0 * local.global_id[i],
                                             local.position[i].x());
      CHECK(comm.sum(static_cast<std::int64_t>(wrong)) == 0);

      // Halo add: every ghost copy contributes 1 to its owner; the total equals the number of
      // ghost copies, and owners see 1 + (number of ranks holding a copy).
      std::vector<double> ones(local.num_local(), 1.0);
      local.halo.exchange(ones, mesh::HaloMode::add);
      double owned_sum = 0;
      for (int i = 0; i < local.num_owned; ++i) owned_sum += ones[i];
      const auto ghosts = comm.sum(static_cast<std::int64_t>(local.num_local() - local.num_owned));
      CHECK(comm.sum(owned_sum) == doctest::Approx(metrics.num_nodes() + ghosts));
      for (int i = local.num_owned; i < local.num_local(); ++i) CHECK(ones[i] == 0.0);
      if (comm.size() == 1) CHECK(ghosts == 0);
    }
  }
}

// partition ghost distance (the immersed kernels' depth, run/immersed_ghosts.hpp): inside the
// box every node nearer than the distance to an owned node is local, whatever the layer count;
// outside it the ghosts stop at ghost_layers; the frontier flags exactly the ghosts with a
// neighbour that is not local.
TEST_CASE("ghost region by distance inside a box") {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::parse_box_cell_type("tetra");
  spec.cells = {16, 12, 10};
  spec.length = Eigen::Vector3d(1.0, 0.6, 0.5);
  spec.perturbation = 0.2;
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const double h = 1.0 / 16, reach = 4.5 * h;  // several layers of these cells
  const mesh::PartitionOptions options{1, mesh::PartitionMethod::metis};
  const mesh::GhostRegion extra{
      reach, Eigen::AlignedBox3d(Eigen::Vector3d(0.3, -1, -1), Eigen::Vector3d(0.7, 2, 2))};
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD, options, extra);
  const auto fixed =
      mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {1, mesh::PartitionMethod::metis});
  REQUIRE(local.frontier.size() == local.dual_node.size());

  const std::int64_t n = metrics.num_nodes();
  std::vector<int> local_of(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < local.num_local(); ++i) local_of[local.dual_node[i]] = i;
  int missing = 0, too_deep_outside = 0, wrong_frontier = 0;
  // The box less the distance: nodes there near an owned node must be local. The BFS measures
  // from the owned node it came from, an upper bound of the true distance; one cell of slack.
  for (std::int64_t d = 0; d < n; ++d) {
    const Eigen::Vector3d& x = metrics.position[d];
    double nearest = 1e300;
    for (int i = 0; i < local.num_owned; ++i)
      nearest = std::min(nearest, (metrics.position[local.dual_node[i]] - x).norm());
    if (local.num_owned > 0 && extra.box.contains(x) && nearest < reach - h && local_of[d] < 0)
      ++missing;
    if (local_of[d] >= local.num_owned && !extra.box.contains(x) &&
        local.ghost_layer[local_of[d]] > options.ghost_layers)
      ++too_deep_outside;
  }
  for (int i = local.num_owned; i < local.num_local(); ++i) {
    bool open = false;
    for (const auto& e : metrics.edges)
      if (e[0] == local.dual_node[i] || e[1] == local.dual_node[i])
        open = open || local_of[e[0] == local.dual_node[i] ? e[1] : e[0]] < 0;
    wrong_frontier += (local.frontier[i] != 0) != open;
  }
  CHECK(missing == 0);
  CHECK(too_deep_outside == 0);
  CHECK(wrong_frontier == 0);
  if (local.comm.size() > 1) {
    // More ghosts than one layer gives, and deeper layers inside the box.
    CHECK(local.comm.sum(std::int64_t(local.num_local() - local.num_owned)) >
          local.comm.sum(std::int64_t(fixed.num_local() - fixed.num_owned)));
    int deepest = 0;
    for (int layer : local.ghost_layer) deepest = std::max(deepest, layer);
    CHECK(local.comm.max(std::int64_t(deepest)) >= 4);
  }
  // Owned nodes and the flow's halo are those of the fixed partition.
  CHECK(local.num_owned == fixed.num_owned);
}
