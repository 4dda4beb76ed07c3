// The LES set-up of a scene ([les]): the reader that goes with declare_les_keys, kept next to
// the declarations (scene/scene_keys_les.cpp).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "analysis/phase_statistics.hpp"
#include "flow/operators.hpp"
#include "io/field_set.hpp"
#include "les/sgs_model.hpp"
#include "mesh/local_mesh.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

struct LesSetup {
  les::SgsKind model = les::SgsKind::none;
  double constant = 0;  // the constant in use (the model's default when les.constant = 0)
  // For flow::ProjectionOptions::subgrid_viscosity; empty for SgsKind::none.
  std::function<void(int, const flow::TensorField&, flow::ScalarField&)> subgrid_viscosity;
  // Appends nu_sgs / nu (or nu_sgs when nu = 0) of the last RK stage to `set` (zero before the
  // first stage), and sgs_energy_fraction / pope_sgs_fraction when output.fields asks for them
  // (les/sgs_energy.hpp, resolved energy from `statistics` or `velocity`,
  // analysis/sgs_energy_field.hpp; les/pope_estimate.hpp with les.integral_length); a no-op for
  // "none". The pointers stay valid until the next call.
  void add_fields(io::FieldSet& set, double time, const flow::VectorField& velocity,
                  const std::vector<analysis::PhaseStatistics>& statistics = {}) const;

  // After a restart: `nu_sgs` (the solver's restored array, run::RunLoop::subgrid_viscosity())
  // is the one the fields show until the first stage refills it.
  void resume(const flow::ScalarField& nu_sgs) const;
  // Thread CPU time spent in the model so far, s (this rank; 0 for "none"): its share of a step
  // (validation/bench les_cost).
  double cpu_seconds() const;

  struct Shared;  // the model, the nu_sgs seen last and the output scratch
  std::shared_ptr<Shared> shared;
};

// Scene checks that need no mesh partition (valsalva check, and run before the run directory is
// touched): output.fields asking for sgs_energy_fraction or pope_sgs_fraction without a model,
// or pope_sgs_fraction without les.integral_length, is a SceneError.
void check_les_scene(const Scene& scene);

// [les] for `local` (filter width = cube root of the dual volume, LocalMesh::h). Throws
// SceneError naming les.constant for a constant the model rejects (and as check_les_scene).
LesSetup les_setup(const Scene& scene, const mesh::LocalMesh& local);

}  // namespace valsalva::scene
