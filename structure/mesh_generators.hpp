// Built-in structured hexahedral meshes: a mapped block, a thin cylindrical shell patch (the
// manufactured leaflet shape) and a straight bar/strip. Every block carries node and surface
// sets for its six sides, "u0", "u1", "v0", "v1", "w0", "w1" (parameter u, v or w at 0 or 1),
// plus descriptive aliases listed with each generator.
#pragma once

#include <array>
#include <functional>

#include "structure/solid_mesh.hpp"

namespace valsalva::structure {

// Hexahedra on the parameter cube [0,1]^3 split in n[0] x n[1] x n[2] elements and mapped to
// space by `map`, which must preserve orientation. Q2 mid-nodes are placed by the map, so
// curved boundaries are followed.
SolidMesh structured_block(HexOrder order, std::array<int, 3> n,
                           const std::function<Vec3(const Vec3&)>& map);

struct ShellPatch {
  double radius = 12.5e-3;      // mid-surface radius [m]
  double angle = 2.0943951024;  // angular span [rad], centred on the +x axis
  double height = 10e-3;        // extent along the cylinder axis z [m]
  double thickness = 0.15e-3;   // [m]
  int n_angle = 16, n_height = 8, n_thickness = 1;
};
// Cylinder axis z; u -> angle, v -> height, w -> radius. Aliases: node/surface sets "side0",
// "side1" (the straight edges at the two ends of the arc), "attachment" (the arc at z = 0),
// "free_edge" (the arc at z = height), surfaces "inner" (concave) and "outer" (convex).
SolidMesh cylindrical_shell_patch(HexOrder order, const ShellPatch& p);

struct Bar {
  Vec3 origin = Vec3::Zero();
  double length = 1, height = 0.1, depth = 0.1;  // along x, y, z [m]
  int n_length = 10, n_height = 1, n_depth = 1;
};
// Aliases: "clamped" (x = origin), "tip" (x = origin + length), "bottom", "top" (y), "back",
// "front" (z).
SolidMesh straight_bar(HexOrder order, const Bar& b);

// Appends `body` to `mesh` as a separate body (its own nodes; orders must match): its node and
// surface sets are added as prefix + name (e.g. "upper_w0"), its nodes and elements renumbered
// after those of `mesh`. Several bodies in one mesh is how contact between bodies is set up.
void append_body(SolidMesh& mesh, const SolidMesh& body, const std::string& prefix);

// Adds node and surface set `alias` as a copy of existing set `name`.
void alias_sets(SolidMesh& mesh, const std::string& name, const std::string& alias);

}  // namespace valsalva::structure
