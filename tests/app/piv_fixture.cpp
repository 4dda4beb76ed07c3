// piv_fixture OUT_DIR: inputs for the compare-piv CLI test. Writes phase statistics (one bin) of
// the linear field u = (0.2 + 0.5 x, 0.4 + 0.1 y, 0.3 x) with RMS a = 0.05 (1 + y) on an 8^3 unit
// box, as a
// run would (OUT_DIR/stats/stats.xmf ...), and one PIV frame of that field on the plane z = 0.5
// (21 x 21 points, |x|, |y| <= 0.3 m about the centre, a deterministic 0.01 m/s ripple so the
// errors are not zero) twice: OUT_DIR/piv_m.csv in m and m/s, OUT_DIR/piv_mm.csv in mm and mm/s.
#include <fmt/format.h>
#include <fmt/os.h>
#include <mpi.h>

#include <cmath>
#include <filesystem>

#include "analysis/phase_statistics.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

using namespace valsalva;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  if (argc != 2) {
    fmt::print(stderr, "usage: piv_fixture OUT_DIR\n");
    MPI_Finalize();
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);
  const auto mesh = mesh::generate_box({});
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local =
      mesh::distribute(mesh, metrics, MPI_COMM_SELF, {2, mesh::PartitionMethod::metis});
  auto mean = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.2 + 0.5 * x.x(), 0.4 + 0.1 * x.y(), 0.3 * x.x());
  };
  const auto nodes = analysis::all_owned_nodes(local);
  analysis::PhaseStatistics stats(local, {0.0, 1, 0.0, 1000.0, "stats"}, nodes);
  auto rms = [](const Eigen::Vector3d& x) { return 0.05 * (1 + x.y()); };
  // Two samples mean +- a: RMS a in every component (not constant, so its correlation is defined).
  for (double sign : {1.0, -1.0}) {
    std::vector<double> values;
    for (int i : nodes) {
      const Eigen::Vector3d u = mean(local.position[i]);
      const double a = sign * rms(local.position[i]);
      values.insert(values.end(), {u.x() + a, u.y() + a, u.z() + a, 0.0});
    }
    stats.add_sample(0, 0, values);
  }
  stats.write(mesh, metrics, out / "stats");
  for (const auto& [name, k] : {std::pair{"piv_m.csv", 1.0}, std::pair{"piv_mm.csv", 1000.0}}) {
    auto f = fmt::output_file((out / name).string());
    f.print("x,y,u,v,u_rms,v_rms\n");
    for (int j = 0; j <= 20; ++j)
      for (int i = 0; i <= 20; ++i) {
        const double x = -0.3 + 0.03 * i, y = -0.3 + 0.03 * j;
        const Eigen::Vector3d p(0.5 + x, 0.5 + y, 0.5), u = mean(p);
        const double ripple = 0.01 * std::sin(7.0 * i + 3.0 * j);
        f.print("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", k * x, k * y,
                k * (u.x() + ripple), k * (u.y() - ripple), k * (rms(p) + ripple),
                k * (rms(p) - ripple));
      }
  }
  MPI_Finalize();
  return 0;
}
