// A straight circular pipe along +z with an inlet and an outlet, built like the periodic pipe
// (mesh/periodic_pipe_generator.hpp): a Gmsh 2D disk triangulation, optionally refined towards the
// wall (mesh/extruded_disk.hpp), extruded into prism layers and split into tetrahedra
// (mesh/prism_split.hpp). Why: Gmsh's 3D Delaunay tetrahedra come out ~30 % coarser than asked and
// scatter at the wall (validation/womersley); the extruded disk puts rows of nodes along the wall
// and a resolution that is the size asked for.
// Patches as mesh/pipe_generator.hpp: "inlet" (z = 0), "outlet" (z = length), "wall"; region
// "fluid".
#pragma once

#include <mpi.h>

#include "mesh/extruded_disk.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::mesh {

struct ExtrudedPipeSpec {
  double radius = 1;        // m
  double length = 1;        // m
  double target_size = 0;   // m, Gmsh's maximum triangle size in the disk
  double layer_height = 0;  // m, the prism layers' height (rounded to length / layers); 0: size
  DiskWallGrading grading;  // m
};

// Collective over `comm`: its rank 0 triangulates the disk and sends it to the others, because
// Gmsh's 2D BoundaryLayer rows are not deterministic (measured: the same spec gives different
// nodes in two calls), while every rank must hold the same mesh. Throws
// std::invalid_argument naming the bad parameter.
mesh::Mesh generate_extruded_pipe_mesh(const ExtrudedPipeSpec& spec, MPI_Comm comm = MPI_COMM_SELF);

}  // namespace valsalva::mesh
