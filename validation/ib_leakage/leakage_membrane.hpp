// The leakage channel's membrane (leakage_setup.hpp) as a finite-element solid: its static
// equilibrium, deflection and centre line, the references the immersed run is measured against.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "structure/material.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::validation {

// The membrane's static equilibrium under a uniform follower pressure `p` on its upstream face
// (clamped at both walls, z held: the slab is periodic), by structure::solve_static: the
// deflection the immersed membrane should reach under the jump it sustains. Returns the
// positions; throws when Newton does not converge.
Eigen::Matrix3Xd membrane_static_shape(const structure::SolidMesh& membrane,
                                       const structure::Material& material, double p);

// Largest downstream displacement of the membrane's nodes from their reference x.
double membrane_deflection(const structure::SolidMesh& membrane, const Eigen::Matrix3Xd& x);

// Mid-surface nodes of the z = 0 layer sorted by y (the membrane's centre line); the mid-surface
// is at x = x_m of a membrane of thickness `thickness`.
std::vector<int> membrane_centre_line(const structure::SolidMesh& membrane, double x_m,
                                      double thickness);

}  // namespace valsalva::validation
