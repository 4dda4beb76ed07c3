// validation::run_scene_file: a level cut short by a stop signal fails instead of being measured
// (a time limit's SIGTERM once let a Womersley level report a zero error from no samples), while
// a run that ends on its own or on the case's own stop request is measured.
#include <doctest/doctest.h>
#include <mpi.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "run/simulation.hpp"
#include "run/stop_signal.hpp"
#include "validation/scene_run.hpp"

using namespace valsalva;

namespace {

// A 4^3 periodic Taylor-Green box, 6 steps.
std::filesystem::path tiny_scene() {
  const auto dir = std::filesystem::temp_directory_path() / "valsalva_test_scene_run";
  std::filesystem::create_directories(dir);
  const auto file = dir / "tiny.toml";
  std::ofstream(file) << R"([mesh]
source = "box"
[mesh.box]
cells = [4, 4, 4]
periodic = ["x", "y", "z"]
[flow]
density = 1.0
viscosity = 0.01
[initial]
type = "taylor_green"
[initial.taylor_green]
velocity = 0.1
length = 0.15915494309189535
[time]
dt = 0.01
end = 0.06
[output]
interval = 0.0
)";
  return file;
}

}  // namespace

TEST_CASE("a level ended by a stop signal throws; one that ends on its own is measured") {
  const auto scene = tiny_scene();
  validation::SceneRun measure;
  int steps_seen = 0;
  measure.observer = [&](const run::Simulation&, std::int64_t) { ++steps_seen; };
  const auto complete = validation::run_scene_file(scene, {}, {}, MPI_COMM_WORLD, measure);
  CHECK(complete.summary.steps == 6);
  CHECK_FALSE(complete.stopped_by_signal);
  CHECK(steps_seen == 6);

  // The case's own stop (e.g. a steady state reached) is a complete level.
  measure.observer = [](const run::Simulation& sim, std::int64_t step) {
    if (step == 3) sim.request_stop();
  };
  const auto steady = validation::run_scene_file(scene, {}, {}, MPI_COMM_WORLD, measure);
  CHECK(steady.summary.stopped);
  CHECK_FALSE(steady.stopped_by_signal);

  measure.observer = [](const run::Simulation&, std::int64_t step) {
    if (step == 2) std::raise(SIGTERM);
  };
  CHECK_THROWS_WITH_AS(validation::run_scene_file(scene, {}, {}, MPI_COMM_WORLD, measure),
                       doctest::Contains("a stop signal ended the level's run"),
                       std::runtime_error);
  run::StopSignal::clear();
  std::filesystem::remove_all(scene.parent_path());
}
