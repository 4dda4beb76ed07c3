// [section.<name>] and [sections]: volume flux through named interior sections
// (io/section_flux.hpp), declared and read in io/scene_keys_sections.cpp.
#pragma once

#include "io/analysis_options.hpp"
#include "io/scene.hpp"

namespace valsalva::io {

// Throws SceneError naming the key for bad names, a zero normal or a box with lo >= hi.
SectionsOptions read_section_options(const Scene& scene);

}  // namespace valsalva::io
