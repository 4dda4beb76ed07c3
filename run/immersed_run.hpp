// The immersed structures of a scene during a run (scene/scene_keys_structure.hpp builds them):
// the coupling the run loop drives (forces spread at every RK stage, markers moved after each
// step, the time step kept below the coupling's bound, re-evaluated as the solids deform), and
// what the run writes about them:
//   structures/<name>.xmf (+ <name>_NNNNNN.h5)  the Lagrangian mesh at every field output with
//       displacement, marker velocity and force [N] and (stresses = true) nodal stresses
//   structures.csv  every immersed.log_every steps: per structure the fluid's load on it [N]
//       (what its clamped nodes pass to the support), the force it applies to the fluid (= the
//       tether reaction: internal forces sum to zero; near 0 when a no-slip wall under the
//       clamped nodes carries the load instead), the tether reaction, the largest marker speed
//       and displacement, the smallest det F and the dt bound in use, and with contact
//       (structure.<name>.contact) the smallest signed gap [m] between its contact surfaces (and
//       the node nearest to it), the contact force [N], the closed area [m^2] and the largest
//       contact pressure [Pa]
//   force_density  the Eulerian force density [N/m^3] joins the fluid fields
// Marker positions and the bound in use go into checkpoints and come back on --restart (so
// that a restarted run takes the same time steps).
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "ibm/immersed_structure.hpp"
#include "io/checkpoint.hpp"
#include "io/solid_series.hpp"
#include "mesh/local_mesh.hpp"
#include "run/run_loop.hpp"
#include "scene/scene_keys_structure.hpp"

namespace valsalva::run {

class ImmersedRun {
 public:
  // Collective. Places every marker in the fluid mesh and evaluates the coupling's time-step
  // bound once; throws std::runtime_error naming the structure when a marker is outside the
  // mesh. `in_place` (a restart in its own run directory) appends to structures.csv and names
  // the Lagrangian series <name>_restart_<start_step>.
  ImmersedRun(scene::ImmersedSetup setup, mesh::LocalMesh& local,
              const std::filesystem::path& run_dir, bool in_place, std::int64_t start_step);

  // For scene::RunOptions::coupling (captures `this`).
  scene::StepCoupling coupling();
  // Collective: the Lagrangian output of every structure (rank 0 writes) and the force density
  // appended to `fields` (valid until the next call).
  void write(double time, io::FieldSet& fields);
  // Collective: the local nodes inside a marker's kernel support at the current positions.
  void support_nodes(std::vector<char>& nodes) { ib_->support_nodes(nodes); }
  // Collective (reductions of nothing: structures are replicated): a row of structures.csv.
  void after_step(double time, std::int64_t step);

  std::vector<io::CheckpointArray> checkpoint_arrays() const;
  void restore(const io::CheckpointReader& in);

  const ibm::ImmersedStructure& structure() const { return *ib_; }
  double dt_bound() const { return dt_bound_; }
  int num_markers() const { return ib_->num_markers(); }

 private:
  double max_dt(std::int64_t step);
  scene::ImmersedSetup setup_;
  mesh::LocalMesh& local_;
  std::unique_ptr<ibm::ImmersedStructure> ib_;
  std::vector<io::SolidSeries> series_;
  std::ofstream csv_;
  flow::VectorField force_density_;
  double dt_bound_ = 0;
  std::int64_t evaluated_at_ = 0;  // step at which dt_bound_ was evaluated
  bool root_ = false;
};

}  // namespace valsalva::run
