// Nodal stresses and strains for output: at each node of each element the Cauchy stress
// sigma = P F^T / J and the Green–Lagrange strain E = (F^T F - I)/2 are evaluated at the node's
// reference coordinates and averaged over the elements sharing the node. Von Mises stress
// sqrt(3/2 dev(sigma):dev(sigma)); principal values sorted in decreasing order.
#pragma once

#include <Eigen/Core>

#include "structure/solid_forces.hpp"

namespace valsalva::structure {

struct NodalStress {
  Eigen::Matrix<double, 6, Eigen::Dynamic> cauchy;  // xx, yy, zz, xy, yz, xz
  Eigen::VectorXd von_mises;
  Eigen::Matrix3Xd principal_stress;
  Eigen::Matrix3Xd principal_strain;  // of the Green–Lagrange strain
};

double von_mises(const Mat3& sigma);
NodalStress nodal_stress(const SolidForces& forces, const Eigen::Matrix3Xd& x);

}  // namespace valsalva::structure
