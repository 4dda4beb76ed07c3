// Manufactured (open) leaflets as Q2 hexahedra, one element through the thickness: a patch of
// the cylinder r = radius about the z axis, bounded below by the parabolic scallop
// z_a(q) = z_base + (z_free - side_attachment - z_base) q^2 (q in [-1, 1] across the span), along
// its two sides by the last side_attachment metres below the free edge, and above by the free
// edge z = z_free. Parameter directions of the mapped block: u along the arc (counter-clockwise
// about +z), v from the scallop to the free edge, w outwards through the thickness, so every
// element's first two reference axes are the leaflet's circumferential and radial directions
// (valve/leaflet_fibres.hpp relies on it).
#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "structure/solid_mesh.hpp"
#include "valve/valve_geometry.hpp"

namespace valsalva::valve {

struct LeafletPatch {
  double radius = 12.5e-3;        // mid-surface [m]
  double thickness = 0.15e-3;     // [m]
  double span = 2.0943951024;     // angular span [rad]
  double centre_angle = 0;        // [rad]
  double z_base = 0;              // lowest attachment point [m]
  double z_free = 10e-3;          // free edge [m]
  double side_attachment = 2e-3;  // [m]
  double free_edge_rise = 0;      // free edge z_free + rise (1 - q^2), q in [-1, 1] across [m]
  // Width of the elements at the posts relative to their mean width along the arc (1: uniform):
  // narrower ones let the closing leaflet bend from its clamped side to its neighbour.
  double side_element_ratio = 1;
  int n_angle = 16, n_height = 8;
};

// Node and surface sets: "attachment" (scallop and both sides, the clamped boundary),
// "free_edge", "aortic_face" (outer, convex, sinus-facing, w = 1) and "ventricular_face"
// (inner, w = 0), and the block sides u0 .. w1 of structured_block.
structure::SolidMesh scalloped_leaflet(const LeafletPatch& p);

// The three leaflets of `g` (Q2 element edges about 1.5 mesh_size, see leaflet_elements) in one
// mesh, leaflet i (1, 2, 3) centred midway between commissures i-1 and i. Sets per leaflet
// "leaflet<i>_attachment", "leaflet<i>_free_edge", "leaflet<i>_aortic_face",
// "leaflet<i>_ventricular_face", node set "leaflet<i>" (all its nodes), and the unions
// "attachment", "free_edge", "aortic_face", "ventricular_face".
structure::SolidMesh valve_leaflets(const ValveGeometry& g);

// Elements of one leaflet along the arc (at the mid-surface radius) and along the height (at the
// leaflet centre): round(length / (1.5 mesh_size)), at least 2 and 1. Q2 node spacing is then
// 0.75 mesh_size, slightly denser than the fluid nodes (a marker spacing at or below the fluid
// spacing keeps the immersed leaflet from leaking); the reference valve gives 16 x 8 per leaflet
// at 1 mm (384 in all, the reference study's M1) and 32 x 16 at 0.5 mm (1536, M2).
std::array<int, 2> leaflet_elements(const ValveGeometry& g);

// Writes leaflets.msh through the Gmsh API: per leaflet a discrete volume of 27-node hexahedra
// (physical volume "leaflet<i>") and discrete surfaces of 9-node quadrangles for its four sets
// (physical surfaces "leaflet<i>_<set>"), plus the physical unions over the leaflets. MSH 4.1.
void write_leaflets_gmsh(const std::filesystem::path& file, const structure::SolidMesh& leaflets);

// Reads leaflets.msh (io::read_solid_gmsh) and checks that the sets above are all there and not
// empty; throws mesh::MeshFileError naming the file and the missing group.
structure::SolidMesh read_valve_leaflets(const std::filesystem::path& file);

// Leaflet i (1, 2, 3) of such a mesh as a mesh of its own, nodes renumbered, with the sets
// "attachment", "free_edge", "aortic_face", "ventricular_face" (from "leaflet<i>_...").
// `positions`, if given (3 x nodes of the full mesh), is restricted the same way into *out.
structure::SolidMesh leaflet_submesh(const structure::SolidMesh& leaflets, int i,
                                     const Eigen::Matrix3Xd* positions = nullptr,
                                     Eigen::Matrix3Xd* out = nullptr);

}  // namespace valsalva::valve
