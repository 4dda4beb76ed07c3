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

// Von Mises stress at the Gauss points of the element's full rule (default_gauss: 3x3x3 for Q2),
// the points the internal forces are integrated at. Unlike the nodal values above they stay
// inside the element, where its map is regular: at a node where an element's map nearly
// degenerates (a clamped corner of a leaflet) the nodal value is not a usable measure.
struct GaussPointStress {
  int points_per_element = 0;
  Eigen::VectorXd von_mises;  // [e * points_per_element + g]
  Eigen::Matrix3Xd position;  // current position of each point [m]
};
GaussPointStress gauss_point_stress(const SolidForces& forces, const Eigen::Matrix3Xd& x);

}  // namespace valsalva::structure
