// `valsalva make-valve OUT_DIR`: valve.toml (the resolved ValveGeometry), leaflets.msh (the three
// manufactured leaflets, valve/leaflet_mesh.hpp) and root.msh (the fluid, valve/root_mesh.hpp),
// and a check that the leaflets' attachment lies in the fluid mesh or on the frame.
#pragma once

#include <filesystem>

#include "valve/root_mesh.hpp"
#include "valve/valve_geometry.hpp"

namespace valsalva::valve {

// Attachment nodes of leaflets.msh located in root.msh: strictly inside a tetrahedron, on the
// fluid boundary (within 5 % of a cell, the chord sag of the curved frame edge at the mesh
// size), or in the frame solid's part buried in the root wall (the aortic-face nodes of
// leaflets whose mid-surface is at the frame's outer radius, as the reference valve's are).
struct AttachmentCheck {
  int nodes = 0, inside = 0, on_boundary = 0, in_frame_wall = 0, lost = 0;
};

struct MakeValveResult {
  int leaflet_elements = 0, leaflet_nodes = 0;
  double leaflet_seconds = 0;
  bool fluid = false;
  RootMeshSummary root;
  AttachmentCheck attachment;
};

// Writes the files into out_dir (created if needed). Refuses, before writing anything, when one
// of them exists and !overwrite. Each mesh is written under a temporary name and renamed when
// complete. `fluid` = false writes valve.toml and leaflets.msh only. The attachment check is
// returned, not enforced (see require_attachment).
MakeValveResult make_valve(const std::filesystem::path& out_dir, const ValveGeometry& g,
                           bool overwrite, bool fluid = true);

// Throws, naming both files, when c.lost > 0.
void require_attachment(const AttachmentCheck& c, const std::filesystem::path& root_msh,
                        const std::filesystem::path& leaflets_msh);

// The attachment check alone, for root.msh and leaflets.msh files of geometry g.
AttachmentCheck check_attachment(const std::filesystem::path& root_msh,
                                 const std::filesystem::path& leaflets_msh, const ValveGeometry& g);

}  // namespace valsalva::valve
