// Mesh of the DFG "flow around a cylinder" channel (Schäfer & Turek, "Benchmark computations of
// laminar flow around a cylinder", Notes Numer. Fluid Mech. 52, 1996): a 2.2 x 0.41 channel
// with a cylinder of diameter 0.1 centred at (0.2, 0.2), as a periodic slab in z. Gmsh's
// OpenCASCADE kernel meshes the 2D section with triangles, graded from size_near on the
// cylinder to size_far at `grading_distance` from it, and extrudes it into `layers` layers of
// tetrahedra (Gmsh cuts each prism into three, the same way in every layer, so the slab is
// z-invariant: tests/io/test_cylinder_channel.cpp) for the consistent P1 Poisson weights, or,
// with split = false, of the prisms themselves. Deterministic (one thread, fixed seed).
// Patches: inlet (x = 0), outlet (x = 2.2), wall (y = 0 and y = 0.41), cylinder, front (z = 0),
// back (z = thickness), to be paired as periodic by the caller; region "fluid".
// Optional refinement box (Turek–Hron: the elastic bar behind the cylinder and its swing): size
// box_size inside [box_x0, box_x1] x [box_y0, box_y1], growing linearly to size_far over
// box_transition outside it; the finer of the two size fields applies.
#pragma once

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

struct CylinderChannelSpec {
  double length = 2.2, height = 0.41;                     // m
  double centre_x = 0.2, centre_y = 0.2;                  // m
  double diameter = 0.1;                                  // m
  double size_near = 0.01, size_far = 0.04;               // m, triangle edge lengths
  double grading_distance = 0.3;                          // m from the cylinder surface
  double thickness = 0.03;                                // m, slab thickness in z
  int layers = 3;                                         // >= 3 so periodic images stay distinct
  double box_size = 0;                                    // m; 0 = no refinement box
  double box_x0 = 0, box_x1 = 0, box_y0 = 0, box_y1 = 0;  // m
  double box_transition = 0.1;                            // m
  bool split = true;  // false: prisms (their weights: flow::slab_stiffness_weights)
};

// Throws std::invalid_argument for an inconsistent spec (cylinder not inside the channel,
// non-positive sizes, fewer than 3 layers, an empty or outside refinement box).
mesh::Mesh generate_cylinder_channel_mesh(const CylinderChannelSpec& spec);

}  // namespace valsalva::mesh
