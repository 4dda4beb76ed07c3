// The subcommands of the valsalva executable. Each returns the process exit code.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "run/simulation.hpp"

namespace valsalva::app {

// `settings`: scene overrides "key=value" (--set, scene::load_scene); `request.quiet`: no
// resolved scene and no progress lines (app/command_run.cpp).
int run_scene(const std::filesystem::path& scene_file, const std::vector<std::string>& settings,
              const run::RunRequest& request);
int check_scene(const std::filesystem::path& scene_file,
                const std::vector<std::string>& settings = {});
int mesh_info(const std::filesystem::path& mesh_file, double scale);
// `settings`: the case options as "key=value" (--set); `show_options` prints the case's
// options instead of running it; `record` stores the report as the case's record of the level
// (validation/record.hpp; refused with `settings`, which change what the levels run).
int validate(const std::string& case_name, bool list, bool quick, const std::string& out,
             const std::vector<std::string>& settings = {}, bool show_options = false,
             bool record = false);
int docs_scenes();
int docs_validation();

}  // namespace valsalva::app
