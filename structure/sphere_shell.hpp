// A closed spherical shell of Q2 hexahedra (scene: structure.<name>.mesh = "sphere_shell"; the
// membrane_relaxation case): the "cubed sphere" (Ronchi, Iacono & Paolucci, J. Comput. Phys.
// 124, 1996): the six faces of a cube, each an n x n x layers structured block, projected
// equiangularly on the sphere, radius through the thickness; coincident nodes on the cube edges
// are merged, so the shell is one conforming closed solid without poles. Surface set "inner" (the
// faces towards the centre) and node sets "inner", "outer".
#pragma once

#include "structure/solid_mesh.hpp"

namespace valsalva::structure {

struct SphereShell {
  Vec3 centre = Vec3::Zero();
  double radius = 0.25;     // mid-surface [m]
  double thickness = 0.04;  // [m]
  int n = 6;                // elements along each cube edge
  int layers = 1;           // elements through the thickness
};

SolidMesh sphere_shell(const SphereShell& s);

// Volume enclosed by the faces of surface set `name` at positions x: (1/3) sum int x . n dA by
// 3x3 Gauss points on each curved Q2 face (orientation taken from the set, absolute value).
double enclosed_volume(const SolidMesh& mesh, const Eigen::Matrix3Xd& x, const std::string& name);

}  // namespace valsalva::structure
