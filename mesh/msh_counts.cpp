#include "mesh/msh_counts.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "core/allocation_limit.hpp"
#include "mesh/gmsh_reader.hpp"

namespace valsalva::mesh {

namespace {

struct Section {
  const char* marker;                // "$Nodes"
  const char* what;                  // "nodes"
  double ascii_bytes, binary_bytes;  // the least one entry takes in the file
};

const Section sections[] = {{"$Nodes", "nodes", 8, 28}, {"$Elements", "elements", 4, 8}};

}  // namespace

void check_msh_counts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return;  // the caller's existence check says why
  const auto size = static_cast<double>(std::filesystem::file_size(path));
  double version = 0;
  bool binary = false;
  std::string line;
  int number = 0, found = 0;
  auto next = [&] {
    if (!std::getline(in, line)) return false;
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  };
  while (found < 2 && next()) {
    if (line == "$MeshFormat") {
      int file_type = 0;
      if (next() && (std::istringstream(line) >> version >> file_type)) binary = file_type == 1;
      continue;
    }
    for (const auto& s : sections) {
      if (line != s.marker) continue;
      ++found;
      double count = 0;
      if (binary && version >= 4) {  // numEntityBlocks, numNodes, minTag, maxTag as size_t
        std::uint64_t header[4] = {};
        if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return;
        count = static_cast<double>(header[1]);
      } else {
        if (!next()) return;
        std::istringstream fields(line);
        if (version >= 4) fields >> count;  // numEntityBlocks first
        if (!(fields >> count)) return;     // a malformed header: Gmsh says so itself
      }
      const double least = binary ? s.binary_bytes : s.ascii_bytes;
      if (count * least > size)
        throw MeshFileError(fmt::format(
            "{}:{}: the {} header declares {:.4g} {}, but the file's {} hold at most {:.0f} "
            "({:g} bytes each at least): a corrupt header, not read (Gmsh would allocate for "
            "all of them)",
            path.string(), number, s.marker, count, s.what, core::byte_size(size),
            std::floor(size / least), least));
    }
  }
}

}  // namespace valsalva::mesh
