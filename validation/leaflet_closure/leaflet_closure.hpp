// The leaflet-closure solve, shared by the validation case and the structure benchmark.
#pragma once

#include "structure/static_solver.hpp"

namespace valsalva::validation {

// Manufactured open leaflet: a 120-degree patch of the aortic-root cylinder (axis z through the
// origin, centred on +x), bounded below by a scalloped attachment curve on the wall,
// z_a(theta) = (height - post) (theta / 60 deg)^2, which rises to the commissural posts (the
// last `post` metres of height at theta = +-60 deg), and above by the free edge at z = height.
struct LeafletGeometry {
  double radius = 12.5e-3, thickness = 0.15e-3, height = 10e-3, post = 2e-3;
  double angle = 2.0943951024;  // 120 degrees
};

struct LeafletClosure {
  structure::SolidMesh mesh;
  structure::NewtonResult result;
  LeafletGeometry geometry;
  double pressure = 0;     // [Pa] on the aortic (outer) face, towards the axis
  int free_edge_mid = -1;  // node: free-edge midpoint on the mid-surface
  double seconds = 0;      // wall time of the static solve
};

// Q2 mesh n_angle x n_height x 1 (valve::scalloped_leaflet) with node/surface sets "attachment"
// (scallop + both posts, the clamped curve including the commissures), "free_edge",
// "ventricular_face" (inner), "aortic_face" (outer).
structure::SolidMesh scalloped_leaflet(const LeafletGeometry& g, int n_angle, int n_height);

// fine: 512 Q2 elements (one leaflet of the reference study's 1536-element mesh), else 128.
LeafletClosure close_leaflet(bool fine, double pressure, bool verbose);

}  // namespace valsalva::validation
