// DFG cylinder-channel slab mesh; see cylinder_channel_generator.hpp.
#include "mesh/cylinder_channel_generator.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "mesh/gmsh_reader.hpp"

namespace valsalva::mesh {

namespace {

void check(const CylinderChannelSpec& s) {
  for (const auto& [name, value] : {std::pair{"length", s.length},
                                    {"height", s.height},
                                    {"diameter", s.diameter},
                                    {"size_near", s.size_near},
                                    {"size_far", s.size_far},
                                    {"grading_distance", s.grading_distance},
                                    {"thickness", s.thickness}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format(
          "generate_cylinder_channel_mesh: {} must be positive and finite, got {}", name, value));
  const double r = s.diameter / 2;
  if (s.centre_x - r <= 0 || s.centre_x + r >= s.length || s.centre_y - r <= 0 ||
      s.centre_y + r >= s.height)
    throw std::invalid_argument(fmt::format(
        "generate_cylinder_channel_mesh: the cylinder (centre ({}, {}), diameter {}) does not lie "
        "strictly inside the {} x {} channel",
        s.centre_x, s.centre_y, s.diameter, s.length, s.height));
  if (s.layers < 3)
    throw std::invalid_argument(fmt::format(
        "generate_cylinder_channel_mesh: layers = {}; at least 3 are needed so that a periodic "
        "node and its image are not neighbours",
        s.layers));
  if (s.box_size != 0 &&
      !(s.box_size > 0 && s.box_x0 < s.box_x1 && s.box_y0 < s.box_y1 && s.box_x0 >= 0 &&
        s.box_x1 <= s.length && s.box_y0 >= 0 && s.box_y1 <= s.height && s.box_transition > 0))
    throw std::invalid_argument(fmt::format(
        "generate_cylinder_channel_mesh: refinement box [{}, {}] x [{}, {}] with size {} and "
        "transition {} must be non-empty, inside the channel and have positive sizes",
        s.box_x0, s.box_x1, s.box_y0, s.box_y1, s.box_size, s.box_transition));
}

}  // namespace

mesh::Mesh generate_cylinder_channel_mesh(const CylinderChannelSpec& s) {
  check(s);
  const std::string source =
      fmt::format("cylinder_channel(size_near={:g}, size_far={:g}, layers={}, box_size={:g}, {})",
                  s.size_near, s.size_far, s.layers, s.box_size, s.split ? "tetra" : "prism");
  GmshSession session;
  gmsh_call(source, [&] {
    namespace occ = gmsh::model::occ;
    gmsh::model::add("cylinder_channel");
    const int channel = occ::addRectangle(0, 0, 0, s.length, s.height);
    const int disk = occ::addDisk(s.centre_x, s.centre_y, 0, s.diameter / 2, s.diameter / 2);
    gmsh::vectorpair section;
    std::vector<gmsh::vectorpair> maps;
    occ::cut({{2, channel}}, {{2, disk}}, section, maps);
    if (section.size() != 1)
      throw MeshFileError(source +
                          ": cutting the cylinder out of the channel did not give one "
                          "surface");
    gmsh::vectorpair extruded;
    // Not recombined, Gmsh cuts each layer's prisms into tetrahedra itself.
    occ::extrude(section, 0, 0, s.thickness, extruded, {s.layers}, {}, !s.split);
    occ::synchronize();

    // Size field: size_near on the circle, growing linearly to size_far at grading_distance.
    gmsh::vectorpair curves;
    gmsh::model::getBoundary(section, curves, false, false, false);
    std::vector<double> circle;
    for (const auto& [dim, tag] : curves) {
      double x = 0, y = 0, z = 0;
      occ::getCenterOfMass(dim, tag, x, y, z);
      if (std::hypot(x - s.centre_x, y - s.centre_y) < 1e-6 * s.diameter) circle.push_back(tag);
    }
    if (circle.empty()) throw MeshFileError(source + ": cylinder curve not found");
    const int distance = gmsh::model::mesh::field::add("Distance");
    gmsh::model::mesh::field::setNumbers(distance, "CurvesList", circle);
    gmsh::model::mesh::field::setNumber(distance, "NumPointsPerCurve", 200);
    const int threshold = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMin", s.size_near);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMax", s.size_far);
    gmsh::model::mesh::field::setNumber(threshold, "DistMin", 0);
    gmsh::model::mesh::field::setNumber(threshold, "DistMax", s.grading_distance);
    int background = threshold;
    if (s.box_size > 0) {
      const int box = gmsh::model::mesh::field::add("Box");
      gmsh::model::mesh::field::setNumber(box, "VIn", s.box_size);
      gmsh::model::mesh::field::setNumber(box, "VOut", s.size_far);
      gmsh::model::mesh::field::setNumber(box, "XMin", s.box_x0);
      gmsh::model::mesh::field::setNumber(box, "XMax", s.box_x1);
      gmsh::model::mesh::field::setNumber(box, "YMin", s.box_y0);
      gmsh::model::mesh::field::setNumber(box, "YMax", s.box_y1);
      gmsh::model::mesh::field::setNumber(box, "ZMin", -1);
      gmsh::model::mesh::field::setNumber(box, "ZMax", s.thickness + 1);
      gmsh::model::mesh::field::setNumber(box, "Thickness", s.box_transition);
      background = gmsh::model::mesh::field::add("Min");
      gmsh::model::mesh::field::setNumbers(
          background, "FieldsList", {static_cast<double>(threshold), static_cast<double>(box)});
    }
    gmsh::model::mesh::field::setAsBackgroundMesh(background);

    // Patches by the centre of mass of each boundary surface of the slab.
    int volume = -1;
    for (const auto& [dim, tag] : extruded)
      if (dim == 3) volume = tag;
    if (volume < 0) throw MeshFileError(source + ": extrusion gave no volume");
    gmsh::vectorpair surfaces;
    gmsh::model::getBoundary({{3, volume}}, surfaces, false, false, false);
    std::map<std::string, std::vector<int>> patches;
    const double tol = 1e-9 * s.length;
    for (const auto& [dim, tag] : surfaces) {
      double x = 0, y = 0, z = 0;
      occ::getCenterOfMass(dim, tag, x, y, z);
      std::string name;
      if (std::abs(z) < tol)
        name = "front";
      else if (std::abs(z - s.thickness) < tol)
        name = "back";
      else if (std::abs(x) < tol)
        name = "inlet";
      else if (std::abs(x - s.length) < tol)
        name = "outlet";
      else if (std::abs(y) < tol || std::abs(y - s.height) < tol)
        name = "wall";
      else
        name = "cylinder";
      patches[name].push_back(tag);
    }
    for (const auto& [name, tags] : patches)
      gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, tags), name);
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "fluid");
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    generate_deterministic_mesh(3);
  });
  return mesh_from_gmsh_model(source);
}

}  // namespace valsalva::mesh
