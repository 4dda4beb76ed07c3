// Tetrahedral mesh of a circular pipe (cylinder along +z) built with Gmsh's OpenCASCADE kernel
// and its 3D Delaunay mesher, run single-threaded with a fixed seed so that the same arguments
// give the same mesh. Patches: "inlet" (z = 0), "outlet" (z = length), "wall"; region "fluid".
#pragma once

#include "flow/mesh.hpp"

namespace valsalva::io {

// radius, length and target_size in metres; target_size is Gmsh's maximum element size.
// Throws std::invalid_argument for non-positive or non-finite arguments.
flow::Mesh generate_pipe_mesh(double radius, double length, double target_size);

}  // namespace valsalva::io
