// Edge-based node-centred finite-volume operators on the median dual of a LocalMesh.
// Every operator loops over the first num_owned_edges local edges (all the edges an owned node
// has), accumulates the edge flux to both ends, adds boundary dual faces, divides by the dual
// volume and finally halo-inserts, so owned AND ghost values of the result are valid.
// Inputs must have valid ghost values (halo-inserted).
//
// Discretisation (vertex-centred FV on median duals, e.g. Barth, "Aspects of unstructured grids
// and finite-volume solvers for the Euler and Navier-Stokes equations", VKI LS 1994-05):
//   gradient      G_j = M_j^-1 (1/V_j) sum_k (phi_k - phi_j)/2 S_jk
//                 (difference form = Green-Gauss with (phi_j+phi_k)/2 on closed dual volumes;
//                 M_j^-1 makes it exact for linear fields, also at boundary nodes)
//   divergence    D_j = (1/V_j) [ sum_k (u_j+u_k)/2 . S_jk + sum_faces u_j . A_j ]
//   Laplacian     flux_jk = a_jk (phi_k - phi_j) + (S_jk - a_jk d_jk) . (G_j + G_k)/2,
//                 a_jk = |S_jk|^2 / (S_jk . d_jk): compact two-point part plus the
//                 non-orthogonal correction, so that it is exact for linear fields on any mesh;
//                 on hexahedral meshes S_jk || d_jk and it is the compact 7-point Laplacian.
//   convection    C_j = (1/V_j) sum_k (u_jk . S_jk) (phi_j + phi_k)/2, u_jk = (u_j + u_k)/2,
//                 2nd-order centred, skew-symmetric part conserves kinetic energy on periodic
//                 meshes; boundary faces add (u_j . A_j) phi_j.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

using ScalarField = std::vector<double>;
using VectorField = std::vector<Eigen::Vector3d>;
using TensorField = std::vector<Eigen::Matrix3d>;  // (i, j) = d u_i / d x_j

// a_jk = |S|^2 / (S . d), the compact Laplacian weight of every local edge.
std::vector<double> laplacian_weights(const mesh::LocalMesh& mesh);

void gradient(const mesh::LocalMesh& mesh, const ScalarField& phi, VectorField& grad);
void gradient(const mesh::LocalMesh& mesh, const VectorField& u, TensorField& grad);
void divergence(const mesh::LocalMesh& mesh, const VectorField& u, ScalarField& div);

// The velocity gradient of gradient() at a few nodes only (e.g. the boundary nodes of
// convective outlets), at the cost of their edges: build the edge list once with
// gradient_edges(mesh, nodes) (the owned ones among `nodes`), then gradient_at() gives those
// nodes bit for bit the values of gradient() (the same edges in the same order), and their
// ghost copies through the halo; other entries of `grad` are left meaningless.
struct GradientSubset {
  std::vector<int> nodes;  // owned
  std::vector<int> edges;  // ascending, each touching one of `nodes`
};
GradientSubset gradient_edges(const mesh::LocalMesh& mesh, const std::vector<int>& nodes);
void gradient_at(const mesh::LocalMesh& mesh, const GradientSubset& subset, const VectorField& u,
                 TensorField& grad);

// The same gradients at owned and layer-1 ghost nodes from local values only (a loop over all
// local edges instead of a halo exchange; layer-2 and deeper values are partial): for the
// 4th-order operators, whose edge corrections need G at both ends. `grad` is resized.
void local_gradient(const mesh::LocalMesh& mesh, const ScalarField& phi, VectorField& grad);
void local_gradient(const mesh::LocalMesh& mesh, const VectorField& u, TensorField& grad);

// Laplacian per unit volume; `grad` is the gradient of phi (from gradient()), used by the
// non-orthogonal correction.
void laplacian(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
               const ScalarField& phi, const VectorField& grad, ScalarField& lap);

// Centred convective term div(u phi) per unit volume for each velocity component: conv_j =
// (1/V_j) sum_k (u_jk . S_jk) (v_j + v_k)/2.
void convection(const mesh::LocalMesh& mesh, const VectorField& u, const VectorField& v,
                VectorField& conv);

// The skew-symmetric 2nd-order convective term carried by the face flux F (one value per local
// edge, flow/face_flux.hpp): conv_j = (1/2V_j) [sum_k F_jk u_k + sum_faces (u_j . A_j) u_j]
// (see flow/convection_scheme.hpp); sum_j V_j u_j . conv_j is the boundary faces' kinetic-energy
// flux to round-off, for any F.
void skew_convection(const mesh::LocalMesh& mesh, const VectorField& u,
                     const std::vector<double>& flux, VectorField& conv);

// Viscous term nu lap(v) for constant nu, per unit volume, componentwise Laplacian with the
// same correction; `grad` is the velocity gradient tensor.
// correction = false: no non-orthogonal correction (the P1 stiffness weights of
// flow::poisson_weights on tetrahedra, whose two-point flux is already the median-dual flux of
// the piecewise-linear field); the boundary-face flux grad v . A is kept either way.
void viscous(const mesh::LocalMesh& mesh, const std::vector<double>& weights, double nu,
             const VectorField& v, const TensorField& grad, VectorField& out,
             bool correction = true);

}  // namespace valsalva::flow
