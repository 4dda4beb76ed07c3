// Gmsh mesh import through Gmsh's own C++ API (libgmsh 4.8): .msh 4.1 ASCII/binary and 2.2
// ASCII. Physical surface groups become boundary patches, physical volume groups regions.
//
// What Gmsh 4.8.4 does on bad input (measured, see tests/io/test_gmsh_reader.cpp):
// - errors are thrown as `std::string` (not std::exception), because the API sets
//   General.AbortOnError = 2; after such a throw Gmsh stays "busy" and silently ignores later
//   gmsh::open calls until gmsh::finalize, so every use goes through a fresh GmshSession;
// - gmsh::open on a missing file neither throws nor logs: we check the file first;
// - a file cut right after a complete section reads "successfully" with fewer sections: we
//   check that the file ends with a $End... marker and that it holds volume elements.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "mesh/mesh.hpp"
#include "mesh/mesh_check.hpp"

namespace valsalva::mesh {

// A mesh file that cannot be read or holds something we do not support.
class MeshFileError : public mesh::MeshError {
 public:
  using mesh::MeshError::MeshError;
};

// Reads a Gmsh mesh. Nodes are renumbered 0..n-1 in file order; cells keep Gmsh node order.
// Throws MeshFileError naming the file (and the element tag and type for unsupported elements).
mesh::Mesh read_gmsh(const std::filesystem::path& path);

// Scoped Gmsh API use: initialise (no config files, silent, one thread) and finalise on exit.
// Gmsh is one global, non-thread-safe state, so sessions may not nest or overlap.
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// Runs f() and turns Gmsh's thrown std::string into MeshFileError("<context>: <gmsh message>").
template <class F>
decltype(auto) gmsh_call(const std::string& context, F&& f) {
  try {
    return f();
  } catch (const std::string& message) {
    throw MeshFileError(context + ": Gmsh: " + message);
  }
}

// Meshes the current model up to `dimension` with linear elements, single-threaded, a fixed
// random seed and no curvature-driven sizes, so that the same model gives the same mesh.
void generate_deterministic_mesh(int dimension);

// Converts the mesh of the current Gmsh model (inside a GmshSession) into a mesh::Mesh;
// `source` names the file or generator in error messages and in Mesh::source.
mesh::Mesh mesh_from_gmsh_model(const std::string& source);

}  // namespace valsalva::mesh
