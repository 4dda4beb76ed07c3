// Scene keys of the fluid mesh (flow/ mesh, io/ mesh import and generators): its source, the
// built-in box and pipe generators, and periodic patch pairs.
#include "mesh/box_generator.hpp"
#include "scene/scene_keys.hpp"

namespace valsalva::scene {

void declare_mesh_keys(Schema& s) {
  s.section("mesh", "Where the fluid mesh comes from.");
  s.choice("mesh.source",
           {"box", "gmsh", "pipe", "cylinder_channel", "periodic_pipe", "extruded_pipe"})
      .required()
      .unit_of("-")
      .doc(
          "Built-in box generator ([mesh.box]), a Gmsh .msh file (mesh.file), a Gmsh-API pipe "
          "([mesh.pipe]), the DFG cylinder channel as a periodic slab ([mesh.cylinder_channel]) or "
          "a streamwise-periodic pipe ([mesh.periodic_pipe]), or a pipe of prism layers split "
          "into tetrahedra, optionally with rows along the wall ([mesh.extruded_pipe])");
  s.string("mesh.file")
      .required()
      .unit_of("-")
      .doc("Gmsh .msh file (4.1 ASCII/binary or 2.2 ASCII), relative to the scene file's folder");
  s.when("mesh.file", "mesh.source", {"gmsh"});
  s.real("mesh.scale")
      .def(1.0)
      .above(0)
      .unit_of("-")
      .doc("Factor applied to all node coordinates, e.g. 0.001 for a mesh drawn in mm");

  s.section("mesh.box", "Box generator: hexahedra, optionally split into other cell types.");
  s.when("mesh.box", "mesh.source", {"box"});
  s.real3("mesh.box.origin")
      .def(std::array{0.0, 0.0, 0.0})
      .unit_of("m")
      .doc("Corner with the smallest coordinates");
  s.real3("mesh.box.length")
      .def(std::array{1.0, 1.0, 1.0})
      .above(0)
      .unit_of("m")
      .doc("Edge lengths along x, y, z");
  s.int3("mesh.box.cells")
      .def(std::array{8, 8, 8})
      .at_least(1)
      .unit_of("-")
      .doc("Number of hexahedral cells along x, y, z");
  s.choice("mesh.box.cell_type", mesh::box_cell_type_names())
      .def("hexa")
      .unit_of("-")
      .doc(
          "Keep hexahedra or split them into tetrahedra, prisms or pyramids; mixed combines "
          "several types");
  s.real("mesh.box.perturbation")
      .def(0.0)
      .in_range(0, 0.4)
      .unit_of("-")
      .doc("Random node displacement, as a fraction of the local cell size h");
  s.integer("mesh.box.seed").def(1).at_least(0).unit_of("-").doc("Seed of the node perturbation");
  s.string_list("mesh.box.periodic")
      .def(std::vector<std::string>{})
      .values({"x", "y", "z"})
      .unit_of("-")
      .doc("Directions in which the box is periodic (its opposite faces are paired)");

  s.section("mesh.pipe", "Pipe generator: Gmsh-API tetrahedral mesh of a circular cylinder.");
  s.when("mesh.pipe", "mesh.source", {"pipe"});
  s.real("mesh.pipe.radius").required().above(0).unit_of("m").doc("Pipe radius");
  s.real("mesh.pipe.length").required().above(0).unit_of("m").doc("Pipe length along its axis");
  s.real("mesh.pipe.size").required().above(0).unit_of("m").doc("Target tetrahedron edge length");

  s.section("mesh.extruded_pipe",
            "Pipe along +z from an inlet (z = 0) to an outlet (z = length) "
            "(mesh/extruded_pipe_generator.hpp): a triangulated disk about the z axis, optionally "
            "refined towards the wall, extruded into prism layers split into tetrahedra; patches "
            "inlet, outlet, wall, region fluid.");
  s.when("mesh.extruded_pipe", "mesh.source", {"extruded_pipe"});
  s.real("mesh.extruded_pipe.radius").required().above(0).unit_of("m").doc("Pipe radius");
  s.real("mesh.extruded_pipe.length").required().above(0).unit_of("m").doc("Pipe length");
  s.real("mesh.extruded_pipe.size")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Largest triangle edge of the disk (Gmsh)");
  s.real("mesh.extruded_pipe.layer_height")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc("Height of the prism layers (rounded to length / layers); 0 = size");
  s.real("mesh.extruded_pipe.wall_size")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc("Triangle size at the wall, growing linearly to size at wall_distance; 0 = none");
  s.real("mesh.extruded_pipe.wall_distance")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc("Distance from the wall over which wall_size grows to size");
  s.real("mesh.extruded_pipe.layer_first")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc("Structured rows along the wall: the first row's height; 0 = no rows");
  s.real("mesh.extruded_pipe.layer_ratio")
      .def(1.2)
      .at_least(1)
      .unit_of("-")
      .doc("Growth ratio of the wall rows");
  s.real("mesh.extruded_pipe.layer_thickness")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc("Total thickness of the wall rows");

  s.section("mesh.periodic_pipe",
            "Streamwise-periodic circular pipe along +z (mesh/periodic_pipe_generator.hpp): a "
            "triangulated disk about the z axis extruded into identical layers from z = 0 to "
            "length; patches wall, zmin, zmax (zmin/zmax paired as periodic), region fluid.");
  s.when("mesh.periodic_pipe", "mesh.source", {"periodic_pipe"});
  s.real("mesh.periodic_pipe.radius").required().above(0).unit_of("m").doc("Pipe radius");
  s.real("mesh.periodic_pipe.length")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Period along z (the pipe's length)");
  s.real("mesh.periodic_pipe.size")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Largest triangle edge of the disk (Gmsh)");
  s.integer("mesh.periodic_pipe.layers")
      .def(3)
      .at_least(3)
      .unit_of("-")
      .doc("Identical cell layers along z (3 at least, so that periodic images stay apart)");
  s.choice("mesh.periodic_pipe.cells", {"tetra", "prism"})
      .def("tetra")
      .unit_of("-")
      .doc(
          "tetra = the prisms split into tetrahedra (the same diagonals in every layer, P1 "
          "Poisson weights); prism = the prisms themselves (two-point Poisson weights)");

  s.section("mesh.cylinder_channel",
            "DFG flow-around-a-cylinder channel (Schaefer & Turek 1996) as a slab of tetrahedra: "
            "graded triangles extruded in z (split into tetrahedra, or prisms: cells); patches "
            "inlet, outlet, wall, cylinder, "
            "front, back (pair front/back in [mesh.periodic.<pair>]).");
  s.when("mesh.cylinder_channel", "mesh.source", {"cylinder_channel"});
  s.real("mesh.cylinder_channel.size_near")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Triangle edge length on the cylinder");
  s.real("mesh.cylinder_channel.size_far")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Triangle edge length from grading_distance away from the cylinder on");
  s.real("mesh.cylinder_channel.grading_distance")
      .def(0.3)
      .above(0)
      .unit_of("m")
      .doc("Distance from the cylinder over which the size grows linearly from near to far");
  s.real("mesh.cylinder_channel.thickness")
      .def(0.03)
      .above(0)
      .unit_of("m")
      .doc("Slab thickness in z");
  s.integer("mesh.cylinder_channel.layers")
      .def(3)
      .at_least(3)
      .unit_of("-")
      .doc("Cell layers across the slab (3 at least, so that periodic images stay apart)");
  s.choice("mesh.cylinder_channel.cells", {"tetra", "prism"})
      .def("tetra")
      .unit_of("-")
      .doc(
          "tetra = the extruded prisms split into tetrahedra; prism = the prisms themselves "
          "(with poisson.weights = prism_slab)");
  s.real("mesh.cylinder_channel.length").def(2.2).above(0).unit_of("m").doc("Channel length");
  s.real("mesh.cylinder_channel.height").def(0.41).above(0).unit_of("m").doc("Channel height");
  s.real("mesh.cylinder_channel.diameter").def(0.1).above(0).unit_of("m").doc("Cylinder diameter");
  s.real("mesh.cylinder_channel.centre_x")
      .def(0.2)
      .unit_of("m")
      .doc("Cylinder centre, x (from the inlet)");
  s.real("mesh.cylinder_channel.centre_y")
      .def(0.2)
      .unit_of("m")
      .doc("Cylinder centre, y (from the lower wall)");
  s.real("mesh.cylinder_channel.box_size")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc(
          "Triangle edge length inside the refinement box [box_x0, box_x1] x [box_y0, box_y1] "
          "(an immersed structure and its swing, e.g. the Turek-Hron bar), growing linearly to "
          "size_far over box_transition outside it; the finer of the cylinder's and the box's "
          "size applies; 0 = no refinement box");
  s.real("mesh.cylinder_channel.box_x0").def(0.0).unit_of("m").doc("Refinement box, lower x");
  s.real("mesh.cylinder_channel.box_x1").def(0.0).unit_of("m").doc("Refinement box, upper x");
  s.real("mesh.cylinder_channel.box_y0").def(0.0).unit_of("m").doc("Refinement box, lower y");
  s.real("mesh.cylinder_channel.box_y1").def(0.0).unit_of("m").doc("Refinement box, upper y");
  s.real("mesh.cylinder_channel.box_transition")
      .def(0.1)
      .above(0)
      .unit_of("m")
      .doc("Distance outside the refinement box over which the size grows to size_far");

  s.section("mesh.periodic.<pair>",
            "Periodic patch pair (any table name): every node of `slave` sits at a node of "
            "`master` + translation.");
  s.string("mesh.periodic.<pair>.master")
      .required()
      .unit_of("-")
      .doc("Name of the master boundary patch");
  s.string("mesh.periodic.<pair>.slave")
      .required()
      .unit_of("-")
      .doc("Name of the slave boundary patch");
  s.real3("mesh.periodic.<pair>.translation")
      .required()
      .unit_of("m")
      .doc("Vector from a master node to its slave node");
}

}  // namespace valsalva::scene
