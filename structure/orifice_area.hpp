// Geometric orifice area of a valve: the part of the annulus disc (radius R, normal to the valve
// axis) that no leaflet covers when projected along the axis. The opening ratio is that area over
// pi R^2.
//
// Method. The projection of a solid along a line equals the projection of its boundary (every
// line through the solid meets its boundary), so only the mesh's boundary faces are projected
// (faces not shared by two elements; this assumes a conforming mesh). Each Q2 (or Q1) boundary
// face is sampled at (n+1)^2 points of its reference square with the element's shape functions at
// the current positions, cut into n x n quadrilaterals and 2 n^2 triangles, and projected. The
// disc is covered by a polar grid (rings x sectors, cell areas exact, so an uncovered disc gives
// pi R^2 to round-off); a cell counts as covered when its centre lies in a projected triangle.
//
// Accuracy. (1) Raster error: only cells the projected outline crosses can be misclassified; for
// an outline that is resolved by the grid (features wider than a cell, radius of curvature larger
// than a cell) the error is at most about half the area of the cells next to the outline, which is
// reported as `raster_error` (cells whose class differs from a neighbour's, summed, halved; cells
// on both sides of the outline are counted, hence the half). It scales as outline length x cell
// size, i.e. first order in 1/rings. Features thinner than a cell (R / rings radially,
// 2 pi r / sectors around) can be missed entirely. (2) Geometric error: straight sub-triangles
// stand for curved Q2 faces; a face of angular span phi about the axis is approximated with
// chords of span phi / n, whose area deficit is about (phi / n)^2 / 6 of the swept area (inscribed
// polygon). Flat faces with straight edges (bilinear images) are represented exactly.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "structure/solid_mesh.hpp"
#include "structure/valve_frame.hpp"

namespace valsalva::structure {

// One leaflet: its mesh and current node positions (3 x mesh->num_nodes()); both must outlive
// the call.
struct LeafletPositions {
  const SolidMesh* mesh = nullptr;
  const Eigen::Matrix3Xd* x = nullptr;
};

struct OrificeOptions {
  int rings = 512;              // radial cells of the polar grid
  int sectors = 0;              // angular cells; 0: the integer nearest 2 pi rings (square at rim)
  int face_subdivision = 4;     // n: each boundary face cut into n x n quadrilaterals
  bool list_uncovered = false;  // fill OrificeArea::uncovered (to draw where the holes are)
};

// One grid cell no leaflet covers: its centre in the annulus plane's own axes (valve_basis) [m]
// and its area [m^2].
struct UncoveredCell {
  Eigen::Vector2d centre;
  double area = 0;
};

struct OrificeArea {
  double area = 0;           // uncovered part of the disc [m^2]
  double disc_area = 0;      // pi R^2 [m^2]
  double opening_ratio = 0;  // area / disc_area
  double raster_error = 0;   // estimate of the rasterisation error of `area` [m^2], see above
  int rings = 0, sectors = 0;
  long triangles = 0;                    // projected triangles
  std::vector<UncoveredCell> uncovered;  // only with OrificeOptions::list_uncovered
};

// Throws std::invalid_argument for a bad valve frame (see valve_basis), no leaflets, a null or
// mismatched leaflet, or options < 1.
OrificeArea geometric_orifice_area(std::span<const LeafletPositions> leaflets,
                                   const ValveFrame& valve, const OrificeOptions& options = {});

}  // namespace valsalva::structure
