// Writes a solid mesh read by read_solid_gmsh back with moved nodes: the source file is opened
// again with Gmsh, the nodes the reader kept (those of hexahedra, in tag order) get the new
// coordinates, and everything else (physical groups, names, other nodes) is kept. Used to store
// a closed valve as the new reference geometry. The file is written to a temporary name beside
// `out` and renamed, so a failure leaves no half-written mesh.
#pragma once

#include <Eigen/Core>
#include <filesystem>

namespace valsalva::io {

// Throws MeshFileError naming the file when it cannot be read or written, or when x does not
// have one column per hexahedron node of the source file.
void write_moved_solid_gmsh(const std::filesystem::path& source, const Eigen::Matrix3Xd& x,
                            const std::filesystem::path& out);

}  // namespace valsalva::io
