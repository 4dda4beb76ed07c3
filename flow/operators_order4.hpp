// 4th-order viscous, gradient and divergence operators on the median dual (nodal point values),
// the counterparts of flow/operators.hpp for ProjectionOptions::fourth_order_operators. They
// follow flow/convection_central4.hpp: a 2nd-order operator plus a correction built from the
// 2nd-order nodal gradient G (flow::gradient) and its gradient H = G(G).
//
// Symmetric node stars (x_j - d is a neighbour whenever x_j + d is, S(-d) = -S(d): uniform
// hexahedra, Kuhn-split tetrahedra), d = x_k - x_j, S = S_jk, Taylor expansion of the edge sums:
//
// gradient and divergence: face values  phi~_jk = (phi_j + phi_k)/2 + (G_j - G_k) . d / 6
//   (central4's u~ = phi_m - d.H.d/24 + O(h^4)). For any flux Q, (1/V) sum_k S . Q(m_jk) has the
//   error (1/48V) sum_k S (d.grad)^3 Q (the even terms cancel in pairs), and the face value
//   Q - (d.grad)^2 Q / 24 cancels it, so
//     Grad4_j = M_j^-1 (1/V_j) sum_k S (phi~_jk - phi_j),  Div4_j = (1/V_j) [sum_k S . u~_jk +
//     sum_faces u_j . A_j]
//   are the point derivatives to O(h^4); G's own O(h^2) error is smooth and enters only as the
//   difference G_j - G_k, i.e. as O(h^4). Only G at owned and layer-1 ghost nodes is needed.
//
// Laplacian (viscous term nu lap v, constant nu): compact edge weights w_jk (the Poisson
//   matrix's: two-point on hexahedra, P1 stiffness on tetrahedra, both consistent on these
//   meshes, sum_k w d d^T / 2V = I) and the edge difference with a Hermite correction,
//     flux_jk = w_jk [ (v_k - v_j) - (d.H_k.d - d.H_j.d) / 12 ],
//   because sum_k w (v_k - v_j) = sum_k w [(d.grad)^2 v / 2 + (d.grad)^4 v / 24 + O(h^6)] and
//   d.H_k.d - d.H_j.d = (d.grad)^3 v + (d.grad)^4 v / 2 + ... (the odd terms cancel in pairs);
//   1/12 removes the h^2 term. In 1D it is v'' + O(h^4) from (v_{i+1} - 2 v_i + v_{i-1})/h^2 -
//   (v''_{i+1} - 2 v''_i + v''_{i-1})/12. The compact part keeps the damping of the odd-even
//   mode; boundary faces add G_j A_j as flow::viscous does. Needs H at layer-1 ghosts, i.e. G at
//   layer-2 ghosts: G is halo-exchanged (flow::gradient does it) and H is summed locally.
//
// On irregular meshes the odd terms do not cancel and the order drops (measured in
// tests/flow/test_operators_order4.cpp). The mesh must have at least 2 ghost layers.
// Allocation-free after the first call.
#pragma once

#include <array>
#include <vector>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

class Order4Operators {
 public:
  // `laplacian_weights`: the compact weights of the viscous operator (flow::poisson_weights).
  Order4Operators(const mesh::LocalMesh& mesh, std::vector<double> laplacian_weights);

  // Owned and ghost values of the results are valid on return; inputs need valid ghosts.
  void gradient(const ScalarField& phi, VectorField& grad);
  void divergence(const VectorField& u, ScalarField& div);
  // nu lap(v); `grad` = flow::gradient(v) with valid ghost values.
  void viscous(double nu, const VectorField& v, const TensorField& grad, VectorField& out);

 private:
  const mesh::LocalMesh& mesh_;
  std::vector<double> weights_;
  VectorField grad_s_;                                   // scalar gradient
  TensorField grad_v_;                                   // vector gradient
  std::vector<std::array<Eigen::Matrix3d, 3>> hessian_;  // per velocity component
};

}  // namespace valsalva::flow
