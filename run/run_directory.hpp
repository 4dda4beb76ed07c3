// The run directory: every result of a run goes there, next to resolved_scene.toml (the scene
// with all defaults) and valsalva_run.toml (the marker: a random run id and the directory's
// absolute path). A non-empty directory is never reused unless the user asks (--overwrite or
// run.overwrite = true), and then only if its marker names it, and only the files and folders
// valsalva writes are deleted: any other entry makes --overwrite refuse, listing it.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "scene/scene.hpp"

namespace valsalva::run {

class RunDirectoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RunDirectory {
 public:
  // Collective over `comm`. Rank 0 creates `dir` (and its parents); an existing non-empty
  // directory is refused unless `overwrite`, and with `overwrite` valsalva's own entries are
  // deleted only if its marker names this directory and nothing else is there (so neither a
  // typo nor a copied scene or marker can wipe a user's folder). Rank 0 then writes the marker
  // and resolved_scene.toml; the other ranks wait. Every rank returns the same directory or
  // throws the same RunDirectoryError.
  static RunDirectory prepare(const std::filesystem::path& dir, bool overwrite,
                              const scene::Scene& scene, MPI_Comm comm);

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path file(std::string_view name) const { return path_ / name; }

  static constexpr std::string_view resolved_scene_name = "resolved_scene.toml";
  static constexpr std::string_view marker_name = "valsalva_run.toml";

 private:
  explicit RunDirectory(std::filesystem::path p) : path_(std::move(p)) {}
  std::filesystem::path path_;
};

// run.output_dir, or runs/<scene file stem> when it is empty (relative to the working folder).
std::filesystem::path default_run_path(const scene::Scene& scene);

}  // namespace valsalva::run
