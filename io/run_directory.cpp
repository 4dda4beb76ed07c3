#include "io/run_directory.hpp"

#include <fmt/format.h>

#include <fstream>
#include <string>
#include <vector>

namespace valsalva::io {
namespace fs = std::filesystem;
namespace {

void check_mpi(int code, const char* what) {
  if (code != MPI_SUCCESS) {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw RunDirectoryError(fmt::format("{} failed: {}", what, std::string(text, length)));
  }
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
      if (!fs::exists(dir / RunDirectory::resolved_scene_name))
        return fmt::format(
            "run directory '{}' is not empty and holds no {}, so it is not a valsalva run "
            "directory; refusing to delete its contents even with --overwrite",
            dir.string(), RunDirectory::resolved_scene_name);
      for (const auto& entry : fs::directory_iterator(dir, ec)) {
        fs::remove_all(entry.path(), ec);
        if (ec) return fmt::format("cannot delete '{}': {}", entry.path().string(), ec.message());
      }
    }
  }
  fs::create_directories(dir, ec);
  if (ec) return fmt::format("cannot create run directory '{}': {}", dir.string(), ec.message());
  const fs::path file = dir / RunDirectory::resolved_scene_name;
  std::ofstream out(file, std::ios::binary);
  out << resolved;
  out.close();
  if (!out) return fmt::format("cannot write '{}'", file.string());
  return {};
}

}  // namespace

RunDirectory RunDirectory::prepare(const fs::path& dir, bool overwrite, const Scene& scene,
                                   MPI_Comm comm) {
  int rank = 0;
  check_mpi(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
  std::string message;
  if (rank == 0) {
    try {
      message = create(dir, overwrite, scene.resolved());
    } catch (const std::exception& e) {  // filesystem_error from iterators, bad_alloc
      message = fmt::format("run directory '{}': {}", dir.string(), e.what());
    }
  }
  // Everyone learns rank 0's outcome, so all ranks fail together.
  int length = static_cast<int>(message.size());
  check_mpi(MPI_Bcast(&length, 1, MPI_INT, 0, comm), "MPI_Bcast");
  message.resize(static_cast<std::size_t>(length));
  if (length > 0) check_mpi(MPI_Bcast(message.data(), length, MPI_CHAR, 0, comm), "MPI_Bcast");
  if (!message.empty()) throw RunDirectoryError(message);
  return RunDirectory(dir);
}

fs::path default_run_path(const Scene& scene) {
  const auto dir = scene.get<std::string>("run.output_dir");
  if (!dir.empty()) return dir;
  return fs::path("runs") / scene.file().stem();
}

}  // namespace valsalva::io
