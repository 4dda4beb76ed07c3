// analysis::RunAnalysis driven by hand on a small periodic box: the statistics' interim files
// appear at start_time + k write_interval with the samples taken so far, a pressure-drop row has
// the volume-weighted region means of a linear pressure (exact), and probes read the state.
#include <doctest/doctest.h>
#include <mpi.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/run_analysis.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

using namespace valsalva;

namespace {

std::vector<std::string> lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

TEST_CASE("run analysis: interim statistics, pressure drop of a linear field, probes") {
  mesh::BoxSpec spec;
  spec.cells = {6, 6, 6};
  spec.periodic = {true, true, true};
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  const auto dir = std::filesystem::path("run_analysis_test_np") +=
      std::to_string(local.comm.size());
  if (local.comm.root()) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  local.comm.barrier();

  analysis::AnalysisOptions a;
  analysis::StatisticsOptions s;
  s.phase = {0.0, 1, 0.0, 1.0, "mean"};
  s.write_interval = 0.5;
  a.statistics = {s};
  a.pressure_drops = {
      {"dx", Eigen::Vector3d(0.25, 0.5, 0.5), Eigen::Vector3d(0.75, 0.5, 0.5), 0.2, 1}};
  a.probes.points = {{"c", Eigen::Vector3d(0.5, 0.5, 0.5)}};
  analysis::RunAnalysis analysis(mesh, metrics, local, a, 1.0, 0.01, dir, false);

  flow::FlowState state;
  state.velocity.assign(local.num_local(), Eigen::Vector3d(1, 2, 3));
  for (int j = 0; j < local.num_local(); ++j) state.pressure.push_back(4 * local.position[j].x());
  const auto phases = dir / "statistics" / "mean_phases.csv";
  const double times[] = {0.0, 0.3, 0.6, 0.9};  // steps 0..3
  for (int step = 0; step < 4; ++step) {
    state.time = times[step];
    analysis.sample(state, step);
    local.comm.barrier();
    if (step == 1) CHECK_FALSE(std::filesystem::exists(phases));  // nothing due before 0.5
    if (step == 2) {  // due at 0.5: written at t = 0.6 with the samples of steps 1 and 2
      REQUIRE(std::filesystem::exists(phases));
      CHECK(lines(phases).at(1) == "0,0,2,1");
    }
  }
  if (local.comm.root()) {
    CHECK(lines(phases).at(1) == "0,0,2,1");  // the next write is due at 1.0: not yet
    // Region means of p = 4 x over spheres symmetric about x = 0.25 / 0.75: 1 and 3 (exact on
    // the uniform box, whose node set is symmetric about each centre), difference -2 Pa.
    const auto drop = lines(dir / "pressure_drop.csv");
    REQUIRE(drop.size() == 5);
    CHECK(drop[0] == "time,dx_upstream,dx_downstream,dx_mmHg");
    double t, up, down, mmhg;
    char c;
    std::istringstream(drop[4]) >> t >> c >> up >> c >> down >> c >> mmhg;
    CHECK(up == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(down == doctest::Approx(3.0).epsilon(1e-12));
    CHECK(mmhg == doctest::Approx(-2.0 / 133.322387415).epsilon(1e-9));
    const auto probes = lines(dir / "probes.csv");
    REQUIRE(probes.size() == 5);
    CHECK(probes[0] == "time,c_u,c_v,c_w,c_p");
    CHECK(probes[4] == "0.90000000000000002,1,2,3,2");
  }
  analysis.finish();
  local.comm.barrier();
  if (local.comm.root()) CHECK(lines(phases).at(1) == "0,0,3,1");  // all three samples
}
