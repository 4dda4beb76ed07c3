#include "mesh/pipe_generator.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "mesh/gmsh_reader.hpp"

namespace valsalva::mesh {

namespace {

// Physical groups inlet / outlet / wall / fluid and the mesh size options of a pipe model;
// `error` when the surfaces are not one inlet, one outlet and some wall.
void name_pipe_groups(const std::string& error, const std::vector<int>& inlet,
                      const std::vector<int>& outlet, const std::vector<int>& wall, int volume,
                      double target_size, int algorithm3d) {
  if (inlet.size() != 1 || outlet.size() != 1 || wall.empty()) throw MeshFileError(error);
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, inlet), "inlet");
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, outlet), "outlet");
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, wall), "wall");
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "fluid");
  gmsh::option::setNumber("Mesh.MeshSizeMax", target_size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
  gmsh::option::setNumber("Mesh.Algorithm3D", algorithm3d);
}

}  // namespace

mesh::Mesh generate_pipe_mesh(double radius, double length, double target_size) {
  return generate_pipe_mesh(radius, length, target_size, PipeMeshOptions{});
}

mesh::Mesh generate_pipe_mesh(double radius, double length, double target_size,
                              const PipeMeshOptions& options) {
  for (const auto& [name, value] :
       {std::pair{"radius", radius}, {"length", length}, {"target_size", target_size}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(
          fmt::format("generate_pipe_mesh: {} must be positive and finite, got {}", name, value));
  if (options.wall_size > 0 && !(options.wall_distance > 0 && std::isfinite(options.wall_distance)))
    throw std::invalid_argument(fmt::format(
        "generate_pipe_mesh: wall_distance must be positive and finite with a wall_size, got {}",
        options.wall_distance));
  const std::string source =
      fmt::format("pipe(radius={:g}, length={:g}, size={:g})", radius, length, target_size);
  GmshSession session;
  gmsh_call(source, [&] {
    gmsh::model::add("pipe");
    const int volume = gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, length, radius);
    gmsh::model::occ::synchronize();
    // The cylinder has three surfaces; tell them apart by the z of their centre of mass.
    gmsh::vectorpair surfaces;
    gmsh::model::getBoundary({{3, volume}}, surfaces, false, false, false);
    std::vector<int> inlet, outlet, wall;
    for (const auto& [dim, tag] : surfaces) {
      double x = 0, y = 0, z = 0;
      gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
      const double r = std::hypot(x, y);
      if (r < 1e-9 * radius && std::abs(z) < 1e-9 * length)
        inlet.push_back(tag);
      else if (r < 1e-9 * radius && std::abs(z - length) < 1e-9 * length)
        outlet.push_back(tag);
      else
        wall.push_back(tag);
    }
    name_pipe_groups(source + ": unexpected cylinder surfaces from OpenCASCADE", inlet, outlet,
                     wall, volume, target_size, options.algorithm3d);
    if (options.wall_size > 0) {
      // The wall distance of the cylinder is R - sqrt(x^2 + y^2): an exact MathEval field.
      const int field = gmsh::model::mesh::field::add("MathEval");
      gmsh::model::mesh::field::setString(
          field, "F",
          fmt::format("Min({1:.17g}, {0:.17g} + ({1:.17g} - {0:.17g}) * Max(0, {2:.17g} - "
                      "Sqrt(x * x + y * y)) / {3:.17g})",
                      options.wall_size, target_size, radius, options.wall_distance));
      gmsh::model::mesh::field::setAsBackgroundMesh(field);
      // The bulk keeps target_size: the small wall size must not spread inwards.
      gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    }
    generate_deterministic_mesh(3);
  });
  return mesh_from_gmsh_model(source);
}

mesh::Mesh generate_bent_pipe_mesh(double radius, double bend_radius, double angle,
                                   double target_size) {
  for (const auto& [name, value] : {std::pair{"radius", radius},
                                    {"bend_radius", bend_radius},
                                    {"angle", angle},
                                    {"target_size", target_size}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format(
          "generate_bent_pipe_mesh: {} must be positive and finite, got {}", name, value));
  if (!(bend_radius > radius) || !(angle < 2 * std::numbers::pi))
    throw std::invalid_argument(fmt::format(
        "generate_bent_pipe_mesh: need bend_radius > radius and angle < 2 pi, got bend_radius {} "
        "radius {} angle {}",
        bend_radius, radius, angle));
  const std::string source = fmt::format(
      "bent_pipe(radius={:g}, bend_radius={:g}, angle={:g}, "
      "size={:g})",
      radius, bend_radius, angle, target_size);
  GmshSession session;
  gmsh_call(source, [&] {
    gmsh::model::add("bent_pipe");
    const int volume = gmsh::model::occ::addTorus(0, 0, 0, bend_radius, radius, -1, angle);
    gmsh::model::occ::synchronize();
    // The ends are the flat surfaces: centres at polar angle 0 and `angle` on the centre line.
    gmsh::vectorpair surfaces;
    gmsh::model::getBoundary({{3, volume}}, surfaces, false, false, false);
    std::vector<int> inlet, outlet, wall;
    const double tol = 1e-6 * bend_radius;
    for (const auto& [dim, tag] : surfaces) {
      double x = 0, y = 0, z = 0;
      gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
      if (std::hypot(x - bend_radius, y) < tol && std::abs(z) < tol)
        inlet.push_back(tag);
      else if (std::hypot(x - bend_radius * std::cos(angle), y - bend_radius * std::sin(angle)) <
                   tol &&
               std::abs(z) < tol)
        outlet.push_back(tag);
      else
        wall.push_back(tag);
    }
    name_pipe_groups(source + ": unexpected torus surfaces from OpenCASCADE", inlet, outlet, wall,
                     volume, target_size, 1);
    generate_deterministic_mesh(3);
  });
  return mesh_from_gmsh_model(source);
}

}  // namespace valsalva::mesh
