// The fluid's viscosity law of a scene: the reader that goes with declare_rheology_keys
// (scene/scene_keys_rheology.cpp).
#pragma once

#include "flow/viscosity_model.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// flow.viscosity_model and its table ([flow.carreau_yasuda], [flow.casson], [flow.power_law]);
// Newtonian: mu = flow.viscosity. Throws SceneError naming the key of a bad or inconsistent
// parameter (mu_0 < mu_inf, a yield stress without regularisation).
flow::ViscosityModel read_viscosity_model(const Scene& scene);

}  // namespace valsalva::scene
