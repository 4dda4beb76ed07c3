// compare-piv's inputs (analysis/statistics_files.hpp) read back from PhaseStatistics::write, and
// mixed up across two runs on meshes of 729 and 1000 nodes: a bin of one run with the mesh of the
// other is refused naming both files and both node counts, never read out of bounds (issue 23, item
// 2; run under the sanitizers by `make sanitize`).
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "analysis/phase_statistics.hpp"
#include "analysis/statistics_files.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

// One bin of statistics of a uniform flow on a box of n^3 cells, written to dir/stats.
void write_statistics(int n, const fs::path& dir) {
  mesh::BoxSpec spec;
  spec.cells = {n, n, n};
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local =
      mesh::distribute(mesh, metrics, MPI_COMM_SELF, {1, mesh::PartitionMethod::metis});
  const auto nodes = analysis::all_owned_nodes(local);
  analysis::PhaseStatistics stats(local, {0.0, 1, 0.0, 1000.0, "stats"}, nodes);
  for (double u : {1.0, 3.0}) {
    std::vector<double> values;
    for (std::size_t i = 0; i < nodes.size(); ++i) values.insert(values.end(), {u, 0.0, 0.0, 0.0});
    stats.add_sample(0, 0, values);
  }
  stats.write(mesh, metrics, dir);
}

}  // namespace

TEST_CASE("statistics files: read back, and a bin from another run refused") {
  const fs::path dir = fs::temp_directory_path() / ("valsalva_stats_" + std::to_string(getpid()));
  write_statistics(8, dir / "a");
  write_statistics(9, dir / "b");
  const auto mesh_a = dir / "a" / "stats_mesh.h5";
  const auto mesh = analysis::read_statistics_mesh(mesh_a);
  CHECK(mesh.num_nodes() == 729);
  CHECK(mesh.num_cells() == 512);
  CHECK(analysis::read_phase_times(dir / "a" / "stats_phases.csv") == std::vector<double>{0.0});
  const auto own = analysis::read_statistics_bin(dir / "a" / "stats_000000.h5", mesh, mesh_a);
  REQUIRE(own.mean_velocity.size() == 3 * 729);
  CHECK(own.mean_velocity[0] == doctest::Approx(2.0));
  CHECK(own.rms_velocity[0] == doctest::Approx(1.0));
  const std::string expected =
      "b/stats_000000.h5' dataset 'mean_velocity' has 3000 values (3 "
      "per node: 1000 nodes), but the statistics mesh '" +
      mesh_a.string() + "' has 729 nodes";
  CHECK_THROWS_WITH(analysis::read_statistics_bin(dir / "b" / "stats_000000.h5", mesh, mesh_a),
                    doctest::Contains(expected.c_str()));
  fs::remove_all(dir);
}
