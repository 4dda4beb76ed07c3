// A straight circular pipe along +z, periodic in z, built as a 2D triangulated disk (Gmsh's
// OpenCASCADE kernel and 2D mesher, deterministic) extruded into `layers` identical layers with
// layer-major node numbering (node a of layer l is l * N + a). The layers are exact copies, so
// every field u(x, y) is resolved identically on every layer: the discrete parallel flow
// u_z(x, y) e_z of a pressure-gradient driven pipe is then a discrete solution (measured in
// validation/womersley_periodic). Cells are prisms, or the same prisms split into tetrahedra
// (mesh/prism_split.hpp); with layer-major numbering the smallest-index diagonals are the same in
// every layer, so the split mesh is translation invariant in z as well.
// Patches: "wall", "zmin" (z = 0), "zmax" (z = length), paired as periodic (zmin master);
// region "fluid".
#pragma once

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

struct PeriodicPipeSpec {
  double radius = 1;       // m
  double length = 1;       // m, the period in z
  double target_size = 0;  // m, Gmsh's maximum triangle size in the disk
  int layers = 3;          // >= 3 so that a periodic node and its image are not neighbours
  bool split = false;      // true: tetrahedra, false: prisms
};

// Throws std::invalid_argument naming the bad parameter.
mesh::Mesh generate_periodic_pipe_mesh(const PeriodicPipeSpec& spec);

}  // namespace valsalva::mesh
