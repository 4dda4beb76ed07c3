// The flow run options of a scene: the reader that goes with declare_flow_keys, kept next to
// the declarations (io/scene_keys_flow.cpp) so that a key is named in one file only.
#pragma once

#include <filesystem>

#include "flow/run_loop.hpp"
#include "io/scene.hpp"

namespace valsalva::io {

// [flow], [time], [poisson], [initial], [output] and run.log_every as flow::RunOptions; results
// go to `run_dir`. Throws SceneError for values the declarations cannot express (a step count
// that is not a whole number).
flow::RunOptions flow_run_options(const Scene& scene, const std::filesystem::path& run_dir);

}  // namespace valsalva::io
