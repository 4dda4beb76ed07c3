// Tetrahedral mesh of a circular pipe (cylinder along +z) built with Gmsh's OpenCASCADE kernel
// and its 3D Delaunay mesher, run single-threaded with a fixed seed so that the same arguments
// give the same mesh. Patches: "inlet" (z = 0), "outlet" (z = length), "wall"; region "fluid".
#pragma once

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// radius, length and target_size in metres; target_size is Gmsh's maximum element size.
// Throws std::invalid_argument for non-positive or non-finite arguments.
mesh::Mesh generate_pipe_mesh(double radius, double length, double target_size);

// Study knobs of the Gmsh 3D mesher (the defaults are generate_pipe_mesh's). Measured on the
// Womersley pipe (bench_womersley_study --mesh_stats 1): Delaunay tetrahedra come out coarser
// than target_size, median edge 1.23 (D/10) to 1.29 (D/20) target_size; HXT 1.35 at D/20;
// Frontal and the Netgen optimiser need Netgen, which this Gmsh lacks.
struct PipeMeshOptions {
  int algorithm3d = 1;  // Mesh.Algorithm3D: 1 Delaunay, 4 Frontal, 10 HXT
  // wall_size > 0: a wall-graded size, wall_size at the wall growing linearly to target_size at
  // the distance wall_distance (> 0) from it, m.
  double wall_size = 0, wall_distance = 0;
};
mesh::Mesh generate_pipe_mesh(double radius, double length, double target_size,
                              const PipeMeshOptions& options);

// A curved pipe: a section of a torus (OpenCASCADE addTorus) of tube radius `radius` whose
// centre line is an arc of radius `bend_radius` over `angle` radians about the z axis, meshed
// like generate_pipe_mesh (Delaunay, deterministic). Patches "inlet" (the end at angle 0),
// "outlet" (the end at `angle`), "wall"; region "fluid". Throws std::invalid_argument for
// non-positive or non-finite arguments, bend_radius <= radius or angle outside (0, 2 pi).
mesh::Mesh generate_bent_pipe_mesh(double radius, double bend_radius, double angle,
                                   double target_size);

}  // namespace valsalva::mesh
