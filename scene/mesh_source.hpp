// The fluid mesh a scene asks for ([mesh]): built-in box, Gmsh file or Gmsh-API pipe, scaled,
// with the scene's periodic pairs, checked before use.
#pragma once

#include <mpi.h>

#include <string>

#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// Errors in the scene (a periodic patch the mesh lacks, an unreadable file) are SceneErrors
// pointing at the key; errors in the mesh itself name the mesh file, cell or node. Collective
// over `comm` for mesh.source = extruded_pipe (its rank 0 triangulates the disk: Gmsh's
// boundary-layer rows are not deterministic), local otherwise.
mesh::Mesh build_mesh(const Scene& scene, MPI_Comm comm = MPI_COMM_SELF);

// Empty when every cell is connected to every other through shared nodes (periodic pairs
// aside); else a message naming the mesh and one cell of each piece (up to 8).
std::string disconnected_pieces(const mesh::Mesh& mesh);

}  // namespace valsalva::scene
