#include "io/solid_gmsh_writer.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <system_error>

#include "mesh/gmsh_reader.hpp"

namespace valsalva::io {

void write_moved_solid_gmsh(const std::filesystem::path& source, const Eigen::Matrix3Xd& x,
                            const std::filesystem::path& out) {
  const std::string src = source.string();
  mesh::GmshSession session;
  mesh::gmsh_call(src + ": cannot read the file", [&] { gmsh::open(src); });
  mesh::gmsh_call(src, [&] {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 3, -1);
    std::vector<std::size_t> used;  // the reader's numbering: hexahedron nodes in tag order
    for (const auto& n : nodes) used.insert(used.end(), n.begin(), n.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    if (static_cast<long>(used.size()) != x.cols())
      throw mesh::MeshFileError(fmt::format("{}: has {} solid nodes, the positions to write {}",
                                            src, used.size(), x.cols()));
    for (std::size_t i = 0; i < used.size(); ++i)
      gmsh::model::mesh::setNode(used[i], {x(0, i), x(1, i), x(2, i)}, {});
  });
  std::filesystem::path tmp = out;
  tmp += ".partial.msh";
  mesh::gmsh_call(out.string() + ": cannot write the file", [&] {
    gmsh::option::setNumber("Mesh.SaveAll", 1);
    gmsh::write(tmp.string());
  });
  std::error_code ec;
  std::filesystem::rename(tmp, out, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw mesh::MeshFileError(
        fmt::format("{}: cannot write the file ({})", out.string(), ec.message()));
  }
}

}  // namespace valsalva::io
