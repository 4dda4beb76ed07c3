// The immersed structures of a scene ([immersed] and [structure.<name>]): the reader that goes
// with declare_structure_keys (scene/scene_keys_structure.cpp). A scene without [structure.*]
// tables has none, and nothing of ibm/ or structure/ is built for it.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ibm/immersed_structure.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"
#include "structure/material.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::scene {

// One [structure.<name>] table: its Lagrangian mesh placed in the fluid, its material and the
// node sets held by the tether.
struct StructureSetup {
  std::string name;
  structure::SolidMesh mesh;  // reference positions already rotated and translated
  std::unique_ptr<structure::Material> material;
  ibm::BodySpec body;
  bool stresses = true;  // von Mises, principal and Cauchy stresses in the output
  // Where the markers start (initial_stretch, initial_bend); empty: at the reference positions.
  Eigen::Matrix3Xd initial;
};

struct ImmersedSetup {
  ibm::ImmersedOptions options;
  int stability_check_every = 0;  // steps between re-evaluations of the coupling's dt bound
  double dt_safety = 1;           // fraction of that bound used
  int log_every = 1;              // steps between rows of structures.csv
  double damping_in_support = 1;  // immersed.pressure_damping_in_support
  double damping_in_support_at_boundary = 1;  // immersed.pressure_damping_in_support_at_boundary
  std::vector<StructureSetup> structures;
  bool empty() const { return structures.empty(); }
};

// Builds the structures of `scene` in the fluid mesh `mesh` (for the periodic box of the
// markers). Throws SceneError naming the key for a bad generator size, an unknown node set, a
// tether missing its stiffness, material parameters the law rejects, or a structure in a mesh
// whose periodic directions are not along the axes.
ImmersedSetup read_immersed_setup(const Scene& scene, const mesh::Mesh& mesh);

}  // namespace valsalva::scene
