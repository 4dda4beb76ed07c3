// Outward flux sum u . A through every boundary patch of a distributed mesh: the one definition
// the boundary conditions (mass correction, lumped outlets, the log) and the valve monitor use.
#pragma once

#include <vector>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

// Collective. One value per patch of LocalMesh::patch_names (by patch index), m^3/s, summed over
// the owned boundary nodes of all ranks; periodic patches have no boundary entries and get 0.
std::vector<double> patch_fluxes(const mesh::LocalMesh& mesh, const VectorField& u);

}  // namespace valsalva::flow
