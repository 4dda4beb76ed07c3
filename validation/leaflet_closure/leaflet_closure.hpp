// The leaflet-closure solve, shared by the validation case and the structure benchmark.
#pragma once

#include "structure/static_solver.hpp"

namespace valsalva::validation {

struct LeafletClosure {
  structure::SolidMesh mesh;
  structure::NewtonResult result;
  double radius = 0;
  double seconds = 0;  // wall time of the static solve
};

// fine: 512 Q2 elements (one leaflet of the 1536-element reference mesh), else 128.
LeafletClosure close_leaflet(bool fine, double pressure, bool verbose);

}  // namespace valsalva::validation
