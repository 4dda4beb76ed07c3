// The data directory; see data_dir.hpp.
#include "run/data_dir.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace valsalva::run {

namespace fs = std::filesystem;

fs::path data_dir() {
  std::vector<fs::path> tried;
  auto holds_data = [&](const fs::path& dir) {
    tried.push_back(dir);
    std::error_code ignored;
    return fs::is_directory(dir / "validation", ignored);
  };
  if (const char* env = std::getenv("VALSALVA_DATA_DIR"); env && *env) {
    if (holds_data(env)) return env;
    throw std::runtime_error(fmt::format(
        "VALSALVA_DATA_DIR = '{}' has no validation/ folder (it should point at the share/"
        "valsalva folder of an installed valsalva, or at its source tree)",
        env));
  }
  std::error_code error;
  const auto exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const auto installed = exe.parent_path().parent_path() / "share" / "valsalva";
    if (holds_data(installed)) return installed;
  }
  if (holds_data(VALSALVA_SOURCE_DIR)) return VALSALVA_SOURCE_DIR;
  std::string places;
  for (const auto& p : tried) places += (places.empty() ? "" : ", ") + p.string();
  throw std::runtime_error(fmt::format(
      "cannot find valsalva's data (validation cases, reference data, plot scripts) in {}: "
      "install valsalva with cmake --install, or set VALSALVA_DATA_DIR",
      places));
}

}  // namespace valsalva::run
