// [section.<name>] and [sections]: volume flux through named interior sections
// (analysis/section_flux.hpp), declared and read in scene/scene_keys_sections.cpp.
#pragma once

#include "analysis/analysis_options.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// Throws SceneError naming the key for bad names, a zero normal or a box with lo >= hi.
analysis::SectionsOptions read_section_options(const Scene& scene);

}  // namespace valsalva::scene
