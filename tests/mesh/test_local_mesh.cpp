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
