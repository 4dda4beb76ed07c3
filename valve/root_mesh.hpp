// The fluid mesh of the valve (root.msh): the lumen of valve/valve_geometry.hpp built with
// Gmsh's OpenCASCADE kernel, the rigid frame cut out of it, linear tetrahedra of size mesh_size.
//
// Construction: inflow cylinder r = R from the inlet to z = ring_height / 2; the sinus region as a
// ruled loft (ThruSections) through closed periodic splines through r_wall(theta, z_k) at 24
// angles, sections every 2 mm up to the STJ (the first and last sections exact circles, so that
// they join the cylinders exactly); the frame cut out of these two; then fused with a cone to
// the aorta and the aorta cylinder to the outlet. The frame
// is the tube R - frame_thickness <= r <= R + bury, 0 <= z <= post_height, from which three lofts
// through radial rectangles above the scallop remove the part between the posts. The frame's
// outer radius R + bury lies inside the root wall (no coincident surfaces for the boolean cut,
// and no film of fluid behind the frame: the wall is at r = R wherever the frame is).
// Boundary patches, classified from their mesh nodes: `inlet` (z = -inlet_length), `outlet`,
// `frame` (every node on the frame's surface), `wall` (the rest: root, sinuses, aorta);
// physical volume `fluid`.
#pragma once

#include <cstddef>
#include <filesystem>

#include "valve/valve_geometry.hpp"

namespace valsalva::valve {

struct RootMeshSummary {
  std::size_t nodes = 0, tetrahedra = 0;
  double cad_volume = 0;  // OpenCASCADE volume of the fluid solid [m^3]
  double seconds = 0;     // geometry + meshing + writing, wall time
  double cad_seconds = 0, surface_seconds = 0, volume_seconds = 0;  // the steps of it
};

// Writes root.msh (MSH 4.1 binary) for `g`. Throws mesh::MeshFileError naming the step when the
// CAD construction fails.
RootMeshSummary write_root_mesh(const std::filesystem::path& file, const ValveGeometry& g);

// Volume of the fluid domain from the parametrisation: cylinders and cone in closed form, the
// sinus region by a midpoint rule on a 1440 x 800 (theta, z) grid of r_wall^2 / 2 (relative
// error below 1e-6), minus the frame inside the lumen, (R^2 - (R - t_f)^2) / 2 times the integral
// of frame_top over theta.
double fluid_volume(const ValveGeometry& g);

// Whether point (x, y, z) lies on or inside the frame solid, within `tolerance` metres.
bool on_frame(const ValveGeometry& g, double x, double y, double z, double tolerance);

}  // namespace valsalva::valve
