// Scene keys of the fluid mesh (flow/ mesh, io/ mesh import and generators): its source, the
// built-in box and pipe generators, and periodic patch pairs.
#include "io/scene_keys.hpp"

namespace valsalva::io {

void declare_mesh_keys(Schema& s) {
  s.section("mesh", "Where the fluid mesh comes from.");
  s.choice("mesh.source", {"box", "gmsh", "pipe", "cylinder_channel", "periodic_pipe"})
      .required()
      .unit_of("-")
      .doc(
          "Built-in box generator ([mesh.box]), a Gmsh .msh file (mesh.file), a Gmsh-API pipe "
          "([mesh.pipe]), the DFG cylinder channel as a periodic slab ([mesh.cylinder_channel]) or "
          "a pipe periodic along its axis ([mesh.periodic_pipe])");
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
  s.choice("mesh.box.cell_type", {"hexa", "tetra", "prism", "pyramid", "mixed"})
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

  s.section("mesh.periodic_pipe",
            "Periodic pipe generator (io/periodic_pipe_generator.hpp): a triangulated disk in the "
            "xy plane, centred on the z axis, extruded along z into identical layers; patches "
            "wall, zmin and zmax, zmin/zmax periodic");
  s.when("mesh.periodic_pipe", "mesh.source", {"periodic_pipe"});
  const std::string pp = "mesh.periodic_pipe.";
  s.real(pp + "radius").required().above(0).unit_of("m").doc("Pipe radius");
  s.real(pp + "length").required().above(0).unit_of("m").doc("Period along z");
  s.real(pp + "size").required().above(0).unit_of("m").doc("Largest triangle size in the disk");
  s.integer(pp + "layers")
      .def(3)
      .at_least(3)
      .unit_of("-")
      .doc("Cell layers along z (3 at least, so that periodic images stay apart)");
  s.choice(pp + "cells", {"prism", "tetra"})
      .def("prism")
      .unit_of("-")
      .doc("prism = the extruded prisms; tetra = the prisms split into tetrahedra");

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

}  // namespace valsalva::io
