// The physical groups a leaflet mesh (valsalva make-valve's leaflets.msh) carries: leaflets
// numbered 1..n, each with node/surface sets "leafletK_attachment", "leafletK_free_edge",
// "leafletK_aortic_face", "leafletK_ventricular_face" and the node set "leafletK" (its volume).
#pragma once

#include <string>
#include <vector>

#include "structure/solid_mesh.hpp"

namespace valsalva::valve {

struct LeafletGroups {
  std::string name;  // "leaflet1"
  std::string attachment, free_edge, aortic_face, ventricular_face;
};

// The leaflets of `mesh`, in order 1..n (n = the largest K with a "leafletK" node set).
// Throws std::invalid_argument naming the mesh's source and the first missing or empty group
// (node sets "leafletK", "leafletK_attachment", "leafletK_free_edge"; surface sets for all four
// "leafletK_<set>"), or "no leaflets" when there is no "leaflet1".
std::vector<LeafletGroups> leaflet_groups(const structure::SolidMesh& mesh);

}  // namespace valsalva::valve
