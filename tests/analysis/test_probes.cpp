// Point location and probes: every cell type (perturbed, so hexahedra and prisms are not affine
// and need the Newton inverse map) reproduces a linear field at random points to round-off;
// the weights sum to one; an outside probe is an error naming it; probe samples have the same
// bits at the world size and at one rank; the CSV keeps all digits.
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "analysis/probes.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

using namespace valsalva;

namespace {

mesh::Mesh box(const std::string& type) {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::parse_box_cell_type(type);
  spec.cells = {5, 4, 4};
  spec.length = Eigen::Vector3d(1.0, 0.8, 0.6);
  spec.origin = Eigen::Vector3d(-0.2, 0.1, 0.3);
  spec.perturbation = 0.15;
  return mesh::generate_box(spec);
}

double linear(const Eigen::Vector3d& x) {
  return 0.3 + 1.7 * x.x() - 2.1 * x.y() + 0.9 * x.z();
}

}  // namespace

TEST_CASE("point locator: linear fields are exact in every cell type") {
  std::mt19937_64 rng(7);
  for (std::string type : {"tetra", "hexa", "prism", "pyramid", "mixed"}) {
    CAPTURE(type);
    const auto mesh = box(type);
    const mesh::PointLocator locator(mesh);
    std::uniform_real_distribution<double> ux(-0.15, 0.75), uy(0.15, 0.85), uz(0.35, 0.85);
    double worst = 0, worst_sum = 0;
    int found = 0;
    for (int k = 0; k < 300; ++k) {
      const Eigen::Vector3d x(ux(rng), uy(rng), uz(rng));
      const auto loc = locator.locate(x);
      if (!loc) continue;  // only in the perturbed boundary layer
      ++found;
      double sum = 0;
      Eigen::Vector3d back = Eigen::Vector3d::Zero();
      for (int j = 0; j < loc->count; ++j) {
        sum += loc->weights[j];
        back += loc->weights[j] * mesh.nodes[loc->nodes[j]];
      }
      worst_sum = std::max(worst_sum, std::abs(sum - 1));
      worst = std::max(
          worst,
          std::abs(loc->interpolate([&](auto n) { return linear(mesh.nodes[n]); }) - linear(x)));
      worst = std::max(worst, (back - x).norm());
    }
    CHECK(found == 300);  // the sample box lies inside the perturbed mesh
    CHECK(worst < 1e-12);
    CHECK(worst_sum < 1e-13);
    // Nodes themselves are found (points on faces, edges and corners of several cells).
    for (mesh::GlobalIndex n = 0; n < mesh.num_nodes(); n += 7)
      CHECK(locator.locate(mesh.nodes[n]));
    CHECK_FALSE(locator.locate(Eigen::Vector3d(5, 0.5, 0.5)));
  }
}

TEST_CASE("probes: same bits at the world size and at one rank; outside probe named") {
  const auto mesh = box("mixed");
  const auto metrics = mesh::compute_dual_metrics(mesh);
  std::vector<analysis::ProbePoint> points = {
      {"inlet", {0.0, 0.3, 0.5}}, {"centre", {0.3, 0.5, 0.6}}, {"near_wall", {0.7, 0.84, 0.8}}};
  auto sample_with = [&](MPI_Comm comm) {
    auto local = mesh::distribute(mesh, metrics, comm, {2, mesh::PartitionMethod::metis});
    flow::FlowState state;
    state.velocity.resize(local.num_local());
    state.pressure.resize(local.num_local());
    for (int i = 0; i < local.num_local(); ++i) {
      const auto& x = local.position[i];
      state.velocity[i] = Eigen::Vector3d(std::sin(3 * x.x()), linear(x), x.y() * x.z() / 3);
      state.pressure[i] = 1e5 * std::cos(x.x() + 2 * x.z());
    }
    const analysis::Probes probes(mesh, metrics, local, points);
    return probes.sample(state);
  };
  const auto world = sample_with(MPI_COMM_WORLD);
  const auto single = sample_with(MPI_COMM_SELF);
  REQUIRE(world.size() == 12);
  for (std::size_t i = 0; i < world.size(); ++i) CHECK(world[i] == single[i]);
  for (std::size_t p = 0; p < points.size(); ++p)
    CHECK(world[4 * p + 1] == doctest::Approx(linear(points[p].position)).epsilon(1e-12));

  auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  CHECK_THROWS_WITH(analysis::Probes(mesh, metrics, local, {{"lost", {0.3, 2.5, 0.6}}}),
                    doctest::Contains("probe 'lost' at (0.3, 2.5, 0.6) m is outside the mesh"));

  // CSV round trip keeps every bit.
  const std::filesystem::path dir = "test_output/probes";
  if (local.comm.root()) std::filesystem::create_directories(dir);
  const analysis::Probes probes(mesh, metrics, local, points);
  {
    analysis::ProbeCsv csv(dir / "probes.csv", probes);
    csv.append(0.1, world);
    csv.append(0.2, single);
  }
  local.comm.barrier();
  const auto series = analysis::read_probe_csv(dir / "probes.csv");
  CHECK(series.columns[0] == "time");
  CHECK(series.columns[5] == "centre_u");
  REQUIRE(series.rows.size() == 2);
  CHECK(series.column("time")[1] == 0.2);
  CHECK(series.column("near_wall_p")[0] == world[11]);
  CHECK_THROWS_WITH(series.column("x_q"), doctest::Contains("no column 'x_q'"));
}
