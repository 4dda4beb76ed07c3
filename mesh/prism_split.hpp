// Conforming split of prisms into tetrahedra (and of their quadrilateral boundary faces into
// triangles) by the smallest-global-index rule of Dompierre, Labbe, Vallet & Camarero, "How to
// subdivide pyramids, prisms and hexahedra into tetrahedra", 8th International Meshing
// Roundtable, 1999: every quadrilateral face is cut along the diagonal through its node of
// smallest index, so two cells sharing a face cut it alike, and each prism then splits into
// three tetrahedra without extra nodes.
// Why: the pressure Poisson matrix uses consistent P1 stiffness weights on all-tetrahedral
// meshes only (flow/poisson_weights.hpp), so extruded slab meshes are turned into tetrahedra.
#pragma once

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// Returns `mesh` with every prism replaced by three positively oriented tetrahedra and every
// quadrilateral boundary face by two triangles; other cells, regions, patches and periodic
// links are kept. Throws mesh::MeshError when the mesh holds pyramids or hexahedra (their quad
// faces would no longer match) or a prism whose three diagonals admit no split.
mesh::Mesh split_prisms_to_tetrahedra(const mesh::Mesh& mesh);

}  // namespace valsalva::mesh
