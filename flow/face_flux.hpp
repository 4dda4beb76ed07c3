// The volume flux through the dual faces, F_e = int u . n dS over the dual face of local edge
// e = (j, k) (oriented j -> k), as a field of its own: the quantity the projection makes
// discretely divergence-free and the convective term carries. A collocated scheme whose
// convective flux is the projected face flux, not an average of the nodal velocities (which
// the approximate projection leaves divergent), is the approach of Mahesh, Constantinescu &
// Moin, J. Comput. Phys. 197, 215-240 (2004) and Ham & Iaccarino, CTR Annual Research Briefs
// 2004; here in node-centred (median-dual) form:
//   predictor   F*_e = S_e . u*_f   with the projection divergence's own face value u*_f
//               ((u_j + u_k)/2, or the Hermite value of flow/operators_order4.hpp)
//   Poisson     (1/V_j) sum_k w_jk (dp_k - dp_j) = rho/dt (1/V_j) [sum_k F*_jk + B_j]
//   correction  F_e = F*_e - dt/rho w_e (dp_k - dp_j)   (w: the Poisson matrix's edge weights)
// so that sum_k F_jk + B_j = 0 at every node to the Poisson tolerance (B_j = sum_faces u_j.A_j).
// Values are valid on every local edge (ghost-ghost edges included) when the inputs have valid
// ghosts; each rank computes a shared edge from the same values, so all ranks agree bit for bit.
#pragma once

#include <vector>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

using EdgeField = std::vector<double>;  // one value per local edge (LocalMesh::edges)

// F_e = S_e . (u_j + u_k)/2 on every local edge (the face value of flow::divergence).
void central_face_flux(const mesh::LocalMesh& mesh, const VectorField& u, EdgeField& flux);

// F_e = S_e . [(u_j + u_k)/2 + (G_j - G_k) d_e / 6] on every local edge (the face value of
// Order4Operators::divergence); `grad` = flow::gradient(u), valid at every local node.
void hermite_face_flux(const mesh::LocalMesh& mesh, const VectorField& u, const TensorField& grad,
                       EdgeField& flux);

// (1/V_j) [sum_k F_jk + sum_faces u_j . A_j] at owned nodes (ghost values 0): the divergence
// the face flux carries, with the boundary faces' flux taken from the nodal velocity u.
void face_flux_divergence(const mesh::LocalMesh& mesh, const EdgeField& flux, const VectorField& u,
                          ScalarField& div);

// F_e += c w_e (phi_k - phi_j) on every local edge (c = -dt/rho: the projection's correction).
void add_compact_gradient(const mesh::LocalMesh& mesh, const std::vector<double>& weights, double c,
                          const ScalarField& phi, EdgeField& flux);

// F_e += c S_e . (g_j + g_k)/2 on every local edge (the wide face value of a nodal gradient g).
void add_central_flux(const mesh::LocalMesh& mesh, double c, const VectorField& g, EdgeField& flux);

}  // namespace valsalva::flow
