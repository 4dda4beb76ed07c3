// `valsalva make-valve OUT_DIR`: valve.toml (the resolved ValveGeometry), leaflets.msh (the three
// manufactured leaflets, valve/leaflet_mesh.hpp) and root.msh (the fluid, valve/root_mesh.hpp),
// and a check that the leaflets' attachment lies in the fluid mesh or on the frame.
#pragma once

#include <array>
#include <filesystem>

#include "valve/root_mesh.hpp"
#include "valve/valve_geometry.hpp"

namespace valsalva::valve {

// Attachment nodes of leaflets.msh located in root.msh: strictly inside a tetrahedron, on the
// fluid boundary (within 5 % of a cell), or else on the frame solid (within 1e-6 root diameters
// of its parametrised surface or inside it): the chord sag of the triangulated, curved scallop
// (h^2 kappa / 8, 0.16 mm at 3 mm, 0.02 mm at 1 mm) puts nodes of the true frame edge just
// outside the tetrahedra, and the aortic-face nodes of leaflets whose mid-surface is at the
// frame's outer radius (the reference valve's) lie in the frame's part within the root wall.
struct AttachmentCheck {
  int nodes = 0, inside = 0, on_boundary = 0, on_frame = 0, lost = 0;
  int first_lost = -1;  // node of leaflets.msh (0-based), for the error message
  std::array<double, 3> first_lost_at{};
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
