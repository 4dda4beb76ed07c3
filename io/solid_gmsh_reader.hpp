// Gmsh import of hexahedral solid meshes (structure::SolidMesh) through the Gmsh API: 8-node
// (Gmsh type 5, Q1) or 27-node (type 12, Q2) hexahedra, all of one kind; Gmsh's node order is
// the order structure/ uses, so connectivity is copied as is. Nodes not used by a hexahedron
// (geometry points, unused mid-nodes) are dropped and the rest renumbered 0..n-1 in tag order.
// Physical groups: every group (any dimension) becomes a node set; physical surfaces made of
// quadrangles (types 3, 10) also become surface sets of hexahedron faces, matched by their
// corner nodes. Names are the physical names, or "physical<dim>_<tag>" for unnamed groups.
#pragma once

#include <filesystem>
#include <string>

#include "structure/solid_mesh.hpp"

namespace valsalva::io {

// Throws mesh::MeshFileError naming the file, and the element type or face for unsupported input
// (no hexahedra, mixed Q1/Q2, other volume elements, a surface quadrangle on no hexahedron).
structure::SolidMesh read_solid_gmsh(const std::filesystem::path& path);

// The same from the current Gmsh model, inside a GmshSession.
structure::SolidMesh solid_mesh_from_gmsh_model(const std::string& source);

}  // namespace valsalva::io
