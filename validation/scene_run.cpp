// Validation levels through run::Simulation; see scene_run.hpp.
#include "validation/scene_run.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>
#include <system_error>

#include "core/comm.hpp"
#include "run/data_dir.hpp"
#include "scene/scene.hpp"

namespace valsalva::validation {

namespace {

namespace fs = std::filesystem;

// A fresh folder made by rank 0 (mkdtemp) and known to every rank; removed on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(MPI_Comm comm) : comm_(comm) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    std::string name;
    if (rank == 0) {
      std::string pattern = (fs::temp_directory_path() / "valsalva-level-XXXXXX").string();
      if (!mkdtemp(pattern.data()))
        throw std::runtime_error(fmt::format("cannot create a scratch run directory {}", pattern));
      name = pattern;
    }
    core::Comm(comm).broadcast(name);
    path_ = name;
  }
  ~ScratchDir() {
    MPI_Barrier(comm_);
    int rank = 0;
    MPI_Comm_rank(comm_, &rank);
    std::error_code ignored;  // a leftover in the temporary directory is no reason to fail
    if (rank == 0) fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  MPI_Comm comm_;
  fs::path path_;
};

}  // namespace

std::filesystem::path case_scene(const std::string& case_name, const std::string& file) {
  return run::data_dir() / "validation" / case_name / file;
}

run::RunRequest level_request(const std::filesystem::path& run_dir) {
  run::RunRequest request;
  request.out = run_dir;
  request.overwrite = true;
  request.quiet = true;
  request.print = false;
  return request;
}

run::RunResult run_scene_file(const std::filesystem::path& scene_file,
                              const std::vector<std::string>& overrides,
                              const std::filesystem::path& run_dir, MPI_Comm comm,
                              const SceneRun& measure) {
  std::optional<ScratchDir> scratch;
  if (run_dir.empty()) scratch.emplace(comm);
  const auto scene = scene::load_scene(scene_file, overrides);
  run::Simulation simulation(scene, level_request(scratch ? scratch->path() : run_dir), comm);
  if (measure.initial_velocity) simulation.set_initial_velocity(measure.initial_velocity);
  if (measure.at_start) measure.at_start(simulation);
  if (measure.modify_velocity) simulation.modify_velocity(measure.modify_velocity);
  if (measure.observer) simulation.observe(measure.observer);
  auto result = simulation.run();
  // A level cut short (e.g. a time limit's SIGTERM) has not produced what its metrics read: the
  // case fails instead of measuring an incomplete run.
  if (result.stopped_by_signal)
    throw std::runtime_error(fmt::format(
        "{}: a stop signal ended the level's run at t = {:.6g} s (step {}), before its end; the "
        "case's metrics would read an incomplete run",
        scene_file.string(), simulation.state().time, result.summary.steps));
  if (measure.at_end) measure.at_end(simulation);
  if (scratch) result.run_path.clear();  // gone with the scratch folder
  return result;
}

}  // namespace valsalva::validation
