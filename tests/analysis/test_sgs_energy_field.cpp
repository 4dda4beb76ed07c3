// Resolved turbulent energy for sgs_energy_fraction: the statistics' k / rho at covered nodes
// once their bin holds 2 samples, |u|^2 / 2 elsewhere; hand-computed values.
#include <doctest/doctest.h>
#include <mpi.h>

#include "analysis/sgs_energy_field.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

using namespace valsalva;

TEST_CASE("resolved turbulent energy: statistics k where covered, |u|^2/2 elsewhere") {
  mesh::BoxSpec spec;
  spec.cells = {4, 4, 4};
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  const double rho = 2.0;
  // Time average (one bin) over the nodes with x <= 0.5.
  std::vector<analysis::PhaseStatistics> stats;
  stats.emplace_back(
      local, analysis::PhaseStatisticsOptions{0.0, 1, 0.0, rho, "s"},
      analysis::nodes_in_box(local, Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(0.5, 2, 2)));
  // Two samples U +- a: mean U = (1, 2, 3), fluctuation a = (0.1, 0.2, 0.3) in every sample, so
  // k / rho = (0.01 + 0.04 + 0.09) / 2 = 0.07; uncovered nodes get |U + a|^2 / 2 of the current
  // velocity (here the second sample): (0.9^2 + 1.8^2 + 2.7^2) / 2 = 5.67.
  const Eigen::Vector3d U(1, 2, 3), a(0.1, 0.2, 0.3);
  flow::FlowState s;
  s.velocity.assign(local.num_local(), U + a);
  s.pressure.assign(local.num_local(), 0.0);
  std::vector<double> k;
  stats[0].add(0.1, s.velocity, s.pressure);
  analysis::resolved_turbulent_energy(local, s.velocity, stats, 0.1, k);
  for (int i = 0; i < local.num_owned; ++i)  // one sample: no fluctuation yet, |u|^2/2 everywhere
    CHECK(k[i] == doctest::Approx(0.5 * (U + a).squaredNorm()).epsilon(1e-14));
  s.velocity.assign(local.num_local(), U - a);
  stats[0].add(0.2, s.velocity, s.pressure);
  analysis::resolved_turbulent_energy(local, s.velocity, stats, 0.2, k);
  double covered = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    if (local.position[i].x() <= 0.5) {
      CHECK(k[i] == doctest::Approx(0.07).epsilon(1e-12));
      ++covered;
    } else {
      CHECK(k[i] == doctest::Approx(5.67).epsilon(1e-14));
    }
  }
  CHECK(local.comm.sum(covered) == 3 * 5 * 5);  // x = 0, 0.25, 0.5 of the 5 x 5 x 5 nodes
}
