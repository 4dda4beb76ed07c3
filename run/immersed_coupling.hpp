// The coupling of a scene's immersed structures to the fluid, built once for `valsalva run`
// (run/immersed_run.hpp) and for `valsalva check`: every marker placed in the fluid mesh and the
// explicit coupling's time-step bound evaluated, so that check refuses what run would refuse.
#pragma once

#include <memory>

#include "ibm/immersed_structure.hpp"
#include "mesh/local_mesh.hpp"
#include "scene/scene_keys_structure.hpp"

namespace valsalva::run {

struct ImmersedCoupling {
  std::unique_ptr<ibm::ImmersedStructure> structure;
  double dt_bound = 0;  // the coupling's stable time step times immersed.dt_safety [s]
};

// Collective. `setup` and `local` must outlive the result (the bodies keep references). Throws
// std::runtime_error naming the structures' marker ranges when a marker is outside the fluid
// mesh or beyond its boundary, or when the bound cannot be evaluated.
ImmersedCoupling build_immersed_coupling(const scene::ImmersedSetup& setup, mesh::LocalMesh& local);

}  // namespace valsalva::run
