// A validation level run as users run it: a case's scene file with the level's overrides
// (`valsalva run SCENE --set KEY=VALUE ...`), through run::Simulation and its one run loop, into
// a run directory of its own (issue 20: the validated code is the code users run).
#pragma once

#include <mpi.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "run/simulation.hpp"

namespace valsalva::validation {

// validation/<case>/<file> in the source tree (the scenes ship with their cases).
std::filesystem::path case_scene(const std::string& case_name, const std::string& file);

// How a validation level runs: into `run_dir`, replacing an earlier level's results there,
// nothing on stdout. For cases that keep the Simulation (run_scene_file does this for them).
run::RunRequest level_request(const std::filesystem::path& run_dir);

struct SceneRun {
  // A start other than initial.type's, u(x) at every node (Simulation::set_initial_velocity),
  // e.g. a periodic reference solution at t = 0; empty: the scene's.
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> initial_velocity;
  // What the case measures: called on every rank before the first step, ...
  std::function<void(const run::Simulation&)> at_start;
  // ... may change the velocity right after every step (Simulation::modify_velocity), ...
  run::VelocityModifier modify_velocity;
  // ... after every step (collective) ...
  run::StepObserver observer;
  // ... and once at the end, with the simulation in its final state (collective).
  std::function<void(const run::Simulation&)> at_end;
};

// Loads `scene_file` with `overrides` and runs it quietly (nothing on stdout) into `run_dir`,
// replacing what is there; an empty `run_dir` runs in a scratch folder under the system's
// temporary directory (the same on every rank), removed afterwards. Collective over `comm`.
// Throws std::runtime_error when a stop signal (SIGINT, SIGTERM) ended the run early.
run::RunResult run_scene_file(const std::filesystem::path& scene_file,
                              const std::vector<std::string>& overrides,
                              const std::filesystem::path& run_dir, MPI_Comm comm,
                              const SceneRun& measure = {});

}  // namespace valsalva::validation
