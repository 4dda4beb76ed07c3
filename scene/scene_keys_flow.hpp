// The flow run options of a scene: the reader that goes with declare_flow_keys, kept next to
// the declarations (scene/scene_keys_flow.cpp) so that a key is named in one file only.
#pragma once

#include <filesystem>

#include "scene/run_options.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// [flow], [time], [poisson], [initial], [output] and run.log_every as scene::RunOptions; results
// go to `run_dir`. Throws SceneError for values the declarations cannot express (a step count
// that is not a whole number).
scene::RunOptions flow_run_options(const Scene& scene, const std::filesystem::path& run_dir);
// [forcing] (scene/scene_keys_forcing.cpp); part of flow_run_options.
flow::ForcingSpec read_forcing(const Scene& scene);
// forcing.type = flow_rate against the boundary conditions: walls and slip walls only (the
// controller sets the flux of a closed periodic domain). Throws SceneError naming forcing.type.
void check_forcing(const Scene& scene, const std::vector<flow::BoundarySpec>& boundary);

// A time step from time.cfl and time.fourier (time.dt = 0) bounded by the viscous (Fourier) limit
// on this mesh: refused, naming flow.density (or flow.viscosity), when that bound alone implies
// more steps to time.end than a fixed time.dt may take (1e9) without time.max_steps.
void check_step_count(const Scene& scene, const mesh::DualMetrics& metrics);

// The initial state against the mesh: a Taylor-Green start needs a mesh periodic in x and y
// with translations that are whole multiples of 2 pi L (else the "exact solution" the run's
// error is measured against is not one). Throws SceneError naming initial.taylor_green.length.
void check_initial_state(const Scene& scene, const mesh::Mesh& mesh);

}  // namespace valsalva::scene
