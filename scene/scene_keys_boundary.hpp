// The boundary conditions of a scene ([boundary.<patch>] tables, declared in
// scene/scene_keys_boundary.cpp) as flow::BoundarySpec, checked against the mesh's patches.
#pragma once

#include <vector>

#include "flow/boundary_conditions.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// Throws SceneError (FILE:LINE): a [boundary.X] table for a patch the mesh lacks (listing the
// mesh's patches) or for a periodic patch, a non-periodic patch without a table (naming it and
// the accepted types), a waveform CSV that cannot be read (naming the CSV file and line).
std::vector<flow::BoundarySpec> read_boundary_conditions(const Scene& scene,
                                                         const mesh::Mesh& mesh);

}  // namespace valsalva::scene
