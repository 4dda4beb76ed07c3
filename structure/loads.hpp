// External loads on a hexahedral solid: body force and dead traction (fixed in the reference
// configuration), and follower pressure, which acts on the current surface along its current
// normal: f_a = -p int N_a n da, with n da = x_s x x_t ds dt on a face parametrised by (s, t);
// its stiffness -df/dx is not symmetric (Bonet & Wood 2008, sec. 9.5; Simo, Taylor, Wriggers,
// CMAME 1991).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "structure/solid_mesh.hpp"

namespace valsalva::structure {

// f += int_V0 N_a b0 dV0, b0 a force per reference volume (rho0 g) [N/m^3].
void add_body_force(const SolidMesh& mesh, const Vec3& b0, Eigen::Matrix3Xd& f);
// f += int_A0 N_a t0 dA0 on the faces, t0 a force per reference area [Pa].
void add_dead_traction(const SolidMesh& mesh, const std::vector<FaceRef>& faces, const Vec3& t0,
                       Eigen::Matrix3Xd& f);
// f += -p int N_a n da on the current faces (n the outward normal of the element face, so p > 0
// pushes into the solid). When K is given, adds the load stiffness -df/dx into its pattern.
void add_follower_pressure(const SolidMesh& mesh, const std::vector<FaceRef>& faces, double p,
                           const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& f,
                           Eigen::SparseMatrix<double>* K);
// Current area of a surface set (for tests and diagnostics).
double surface_area(const SolidMesh& mesh, const std::vector<FaceRef>& faces,
                    const Eigen::Matrix3Xd& x);

}  // namespace valsalva::structure
