// A Gmsh 2D triangulated disk (OpenCASCADE kernel, deterministic 2D mesher) extruded along z
// into prism layers with layer-major node numbering (node a of layer l is l * N + a): the shared
// part of the periodic pipe (mesh/periodic_pipe_generator.hpp) and of the inlet/outlet pipe
// (mesh/extruded_pipe_generator.hpp). Every layer is an exact copy of the disk.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace valsalva::mesh {

// Optional refinement of the disk towards its wall (sizes in metres; 0 = off). Why: the Stokes
// layer of an oscillating pipe flow is thinner than a bulk cell (validation/womersley).
struct DiskWallGrading {
  // Isotropic: size wall_size at the wall growing linearly to the bulk size at the distance
  // wall_distance from it (a MathEval field of the exact wall distance R - r).
  double wall_size = 0, wall_distance = 0;
  // Anisotropic structured rows along the wall (Gmsh's BoundaryLayer field, split into
  // triangles): first row height layer_first, growing by layer_ratio up to layer_thickness.
  double layer_first = 0, layer_ratio = 1.2, layer_thickness = 0;
};

struct Disk {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from +z
};

// Throws std::invalid_argument for a bad grading, MeshFileError when Gmsh fails.
Disk triangulate_disk(double radius, double size, const DiskWallGrading& grading,
                      const std::string& source);

// Prisms between the consecutive levels z[0] < z[1] < ... (every node of a level has exactly
// that z); region "fluid", patches "wall" (the side, quads facing outwards), `bottom` (z[0])
// and `top` (z.back()), in that order.
mesh::Mesh extrude_disk(const Disk& disk, const std::vector<double>& z, const std::string& bottom,
                        const std::string& top, const std::string& source);

}  // namespace valsalva::mesh
