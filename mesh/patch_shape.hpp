// How close a boundary patch is to a disc, for the inlet profiles that assume a circular section
// (Poiseuille, Womersley: centre = area-weighted centroid, radius = the largest distance of a
// patch node from it, flow/boundary_conditions.hpp).
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

struct PatchShape {
  double area = 0;         // |sum of the faces' area vectors|, m^2 (the projected area)
  double max_radius = 0;   // largest distance of a patch node from the centroid, off the normal
  double circularity = 0;  // max_radius / sqrt(area / pi): 1 for a disc, above 1 otherwise
};

PatchShape patch_shape(const mesh::Mesh& mesh, int patch);

// Largest circularity accepted for a circular-section profile. A regular polygon of N sides
// inscribed in a circle has sqrt(pi / (N/2 sin(2 pi / N))): 1.100 for a hexagon (the coarsest
// section one would mesh a circle with), 1.054 for 8 sides; Gmsh pipe inlets measure 1.008 at
// size D/6.7 and 1.020 at Gmsh's coarsest (14 sides, tests/io/test_patch_shape.cpp); a square
// gives 1.253, a 2:1 rectangle 1.40, an equilateral triangle 1.56, an ellipse
// sqrt(a/b) (refused beyond 1.25:1).
inline constexpr double max_circularity = 1.12;

}  // namespace valsalva::mesh
