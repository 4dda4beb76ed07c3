// One simulation assembled from a scene — mesh, partition, solver, boundary conditions, LES,
// immersed structures, valve monitor, analysis, fields and checkpoints — and its one run loop.
// `valsalva run`, every validation case and every benchmark that times a run go through it, so
// that what is validated is what users run (issue 20).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"
#include "run/run_loop.hpp"
#include "scene/scene.hpp"

namespace valsalva::ibm {
class ImmersedStructure;
}

namespace valsalva::analysis {
class RunAnalysis;
}

namespace valsalva::run {

// How a run is started, apart from the scene: the command line of `valsalva run`.
struct RunRequest {
  std::filesystem::path out;  // empty: run.output_dir, else runs/<scene>
  bool overwrite = false;     // or run.overwrite: replace an earlier run's directory
  std::string restart;        // "": a new run; a checkpoint file; "latest" in <out>/checkpoints
  bool quiet = false;         // start and end lines only (run.progress = quiet)
  bool print = true;          // false: nothing on stdout at all (tests, validation levels)
};

struct RunResult {
  run::RunSummary summary;
  std::filesystem::path run_path;         // the run directory (log.csv and the rest)
  std::filesystem::path fields_xmf;       // empty without field output
  std::filesystem::path last_checkpoint;  // empty when none was written
  // SIGINT or SIGTERM on some rank ended the run early (summary.stopped; the same on every rank).
  bool stopped_by_signal = false;
};

class Simulation;
// Called on every rank after every step, after the analysis sampled it (collective).
using StepObserver = std::function<void(const Simulation&, std::int64_t step)>;
// Called on every rank right after every step, before the checks, the analysis and the
// observer: may change the velocity (all local nodes), e.g. a validation case's rescaling to a
// target spectrum during a spin-up (validation/cbc_decay). Collective.
using VelocityModifier =
    std::function<void(const Simulation&, flow::VectorField& velocity, std::int64_t step)>;

class Simulation {
 public:
  // Checks the whole scene against its mesh before the run directory is touched, then prepares
  // the directory (or continues one in place on a restart) and sets everything up. Throws
  // scene::SceneError / std::runtime_error naming the key, file or checkpoint at fault.
  Simulation(const scene::Scene& scene, const RunRequest& request, MPI_Comm comm = MPI_COMM_WORLD);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Before run(), not on a restart: start from u(x) at every node instead of initial.type's
  // velocity (boundary values imposed on it), e.g. a validation level from the coarser level's
  // steady field.
  void set_initial_velocity(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u);
  // Something a validation case or benchmark measures on the way; nothing by default.
  void observe(StepObserver observer);
  // Before run(): change the velocity after every step (nothing by default).
  void modify_velocity(VelocityModifier modifier);
  // Runs to time.end (or time.max_steps, or a stop signal), writes the analysis results.
  // Throws run::RunError as std::runtime_error with the scene key's location when it names one.
  RunResult run();

  // From an observer: end the run after this step (RunSummary::stopped), e.g. once a
  // validation case's quantity is steady.
  void request_stop() const;  // const: observers receive the simulation read-only

  const mesh::Mesh& mesh() const;
  const mesh::DualMetrics& metrics() const;
  const mesh::LocalMesh& local() const;
  const flow::FlowState& state() const;
  const run::RunLoop& loop() const;
  // The immersed structures, or nullptr in a scene without [structure.<name>] tables.
  const ibm::ImmersedStructure* immersed() const;
  const std::filesystem::path& run_path() const;
  // What the scene measures ([wall_shear], [statistics], ...), null when it asks for nothing:
  // e.g. a validation case's observer reading the wall shear stress of the step.
  const analysis::RunAnalysis* analysis() const;
  // Thread CPU time this rank spent in the subgrid model so far, s (0 without [les] model).
  double subgrid_cpu_seconds() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace valsalva::run
