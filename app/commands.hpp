// The subcommands of the valsalva executable. Each returns the process exit code.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::app {

// `restart`: empty, a checkpoint file, or "latest" (newest in <run dir>/checkpoints);
// `quiet`: no resolved scene and no progress lines (app/command_run.cpp).
int run_scene(const std::filesystem::path& scene_file, bool overwrite, const std::string& out,
              const std::string& restart = {}, bool quiet = false);
int check_scene(const std::filesystem::path& scene_file);
int mesh_info(const std::filesystem::path& mesh_file, double scale);
// `settings`: the case options as "key=value" (--set); `show_options` prints the case's
// options instead of running it.
int validate(const std::string& case_name, bool list, bool quick, const std::string& out,
             const std::vector<std::string>& settings = {}, bool show_options = false);
int docs_scenes();

}  // namespace valsalva::app
