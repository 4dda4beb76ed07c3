#include "run/run_directory.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "core/comm.hpp"

namespace valsalva::run {
namespace fs = std::filesystem;
namespace {

// Every name valsalva writes at the top of a run directory (fields, analysis logs and the
// folders of checkpoints, statistics, samples and Lagrangian meshes); --overwrite deletes these
// and nothing else.
bool written_by_valsalva(const fs::directory_entry& entry) {
  static const std::regex files(
      "resolved_scene(_restart_[0-9]{9})?\\.toml|valsalva_run\\.toml|log\\.csv|probes\\.csv|"
      "pressure_drop\\.csv|wall_shear(_history|_summary)?\\.csv|structures\\.csv|outlets\\.csv|"
      "sections\\.csv|valve(_cycles)?\\.csv|"
      "taylor_green_error\\.csv|(fields(_restart_[0-9]{9})?|last_good|wall_shear_surface)"
      "(\\.xmf|\\.xmf\\.tmp|_mesh\\.h5|_[0-9]{6}\\.h5)");
  static const std::regex folders("checkpoints|statistics|samples|structures");
  const std::string name = entry.path().filename().string();
  std::error_code ec;
  if (entry.is_directory(ec) && !entry.is_symlink(ec)) return std::regex_match(name, folders);
  return entry.is_regular_file(ec) && !entry.is_symlink(ec) && std::regex_match(name, files);
}

std::string absolute_path(const fs::path& dir) {
  std::error_code ec;
  const auto p = fs::weakly_canonical(fs::absolute(dir), ec);
  return (ec ? fs::absolute(dir) : p).string();
}

// The marker's "directory" value, empty when the file is not a valsalva marker.
std::string marked_directory(const fs::path& marker) {
  std::ifstream in(marker);
  std::string line;
  bool identified = false;
  std::string dir;
  static const std::regex id("id = \"[0-9a-f]{32}\"");
  static const std::regex directory("directory = \"(.*)\"");
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_match(line, id)) identified = true;
    if (std::regex_match(line, m, directory)) dir = m[1];
  }
  return identified ? dir : std::string();
}

std::string new_marker(const fs::path& dir) {
  std::random_device random;
  std::string id;
  for (int i = 0; i < 4; ++i) id += fmt::format("{:08x}", random());
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return fmt::format(
      "# Written by valsalva when it created this run directory. `valsalva run --overwrite` "
      "clears\n# a directory only where this file names it, and then deletes only the files "
      "valsalva writes.\nid = \"{}\"\ndirectory = \"{}\"\ncreated = \"{}\"\n",
      id, absolute_path(dir), when);
}

// --overwrite: deletes valsalva's own entries of a directory that its marker names; anything
// else there makes it refuse (listing the entries) before anything is deleted.
std::string clear(const fs::path& dir) {
  const fs::path marker = dir / RunDirectory::marker_name;
  const std::string marked = fs::exists(marker) ? marked_directory(marker) : std::string();
  if (marked.empty())
    return fmt::format(
        "run directory '{}' is not empty and holds no valsalva marker {}, so it is not a "
        "directory valsalva created; refusing to delete its contents even with --overwrite",
        dir.string(), RunDirectory::marker_name);
  if (marked != absolute_path(dir))
    return fmt::format(
        "run directory '{}': its marker {} was written for '{}' (a copied or moved run "
        "directory); refusing to delete its contents even with --overwrite",
        dir.string(), RunDirectory::marker_name, marked);
  std::vector<std::string> unknown;
  std::vector<fs::path> ours;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (written_by_valsalva(entry))
      ours.push_back(entry.path());
    else
      unknown.push_back(entry.path().filename().string());
  }
  if (!unknown.empty()) {
    std::sort(unknown.begin(), unknown.end());
    return fmt::format(
        "run directory '{}' holds entries valsalva did not write: {}; refusing --overwrite "
        "(move them elsewhere, or choose another run.output_dir)",
        dir.string(), fmt::join(unknown, ", "));
  }
  std::error_code ec;
  for (const auto& p : ours) {
    fs::remove_all(p, ec);
    if (ec) return fmt::format("cannot delete '{}': {}", p.string(), ec.message());
  }
  return {};
}

// Rank 0's part; returns an error message, empty on success.
std::string create(const fs::path& dir, bool overwrite, const std::string& resolved) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec))
      return fmt::format("run directory '{}' exists and is not a directory", dir.string());
    if (!fs::is_empty(dir, ec)) {
      if (!overwrite)
        return fmt::format(
            "run directory '{}' is not empty; pass --overwrite or set run.overwrite = true to "
            "replace its contents, or choose another run.output_dir",
            dir.string());
      if (auto error = clear(dir); !error.empty()) return error;
    }
  }
  fs::create_directories(dir, ec);
  if (ec) return fmt::format("cannot create run directory '{}': {}", dir.string(), ec.message());
  for (const auto& [name, text] :
       {std::pair{std::string(RunDirectory::marker_name), new_marker(dir)},
        std::pair{std::string(RunDirectory::resolved_scene_name), resolved}}) {
    std::ofstream out(dir / name, std::ios::binary);
    out << text;
    out.close();
    if (!out) return fmt::format("cannot write '{}'", (dir / name).string());
  }
  return {};
}

}  // namespace

RunDirectory RunDirectory::prepare(const fs::path& dir, bool overwrite, const scene::Scene& scene,
                                   MPI_Comm comm) {
  const core::Comm ranks(comm);
  std::string message;
  if (ranks.root()) {
    try {
      message = create(dir, overwrite, scene.resolved());
    } catch (const std::exception& e) {  // filesystem_error from iterators, bad_alloc
      message = fmt::format("run directory '{}': {}", dir.string(), e.what());
    }
  }
  // Everyone learns rank 0's outcome, so all ranks fail together.
  ranks.broadcast(message);
  if (!message.empty()) throw RunDirectoryError(message);
  return RunDirectory(dir);
}

fs::path default_run_path(const scene::Scene& scene) {
  const auto dir = scene.get<std::string>("run.output_dir");
  if (!dir.empty()) return dir;
  return fs::path("runs") / scene.file().stem();
}

}  // namespace valsalva::run
