// 4th-order centred convection div(u u) on the median dual, edge-based, nodal (point) values.
//
// Sources: the YALES2 4th-order scheme (Moureau, Domingo & Vervisch, "Design of a massively
// parallel CFD code for complex geometries", C. R. Mecanique 339, 141-148, 2011; M. Kraushaar,
// PhD thesis, INP Toulouse / CERFACS, 2011): nodal values from dual-volume averages by
// deconvolution, Hermite-type face values. The edge form below is the kappa = 1/3 edge-based
// reconstruction (Katz & Sankaran, J. Comput. Phys. 230, 7670-7686, 2011) in centred form.
//
// Form::edge4 (scene "central4"), d = x_k - x_j, S = S_jk, G = flow::gradient (2nd order):
//   u~_jk = (u_j + u_k)/2 + (G_j - G_k) d / 6                      (= u_m - d.H_m.d / 24 + O(h^4))
//   F_jk  = (u~_jk . S) u~_jk - ((u_k - u_j) . S)(u_k - u_j) / 12  (= (P - d.d P / 24)_m, P =
//   (u.S)u) C_j   = (1/V_j) [ sum_k F_jk + sum_faces (u_j . A_j) u_j ]
// Why 1/6 and not the architecture's 1/8: 1/8 gives the midpoint value u_m to O(h^4), but the
// flux difference over a dual volume of a midpoint value is the derivative plus d^2/24 d'''
// (the face is not a point). Taking the value minus d.H.d/24 cancels that term; all other
// O(h^2) terms are even in d and cancel in sum_k on meshes whose node stars are symmetric
// under x -> -x (uniform hexahedra, Kuhn-split tetrahedra), so there C_j = div(u u)(x_j) +
// O(h^4). The gradient's own O(h^2) error is smooth there and enters as (G_j - G_k) d = O(h^4).
// The product term restores the -u'phi'/12 cross term that a product of two interpolated
// values misses. On uniform hexahedra this is the classical 4th-order centred difference
// (7/12, -1/12 weights). On irregular meshes the order drops (measured, tests/flow).
//
// apply(u, flux, conv), the solver's form: the skew-symmetric part of the transport by the
// projected face flux F (flow/convection_scheme.hpp), C_F(u)_j = sum_k F_jk u~_jk(u):
//   V_j conv_j = (1/2) sum_k F_jk u_k + (1/2) [Q(u) - Q^*(u)]_j + B_j u_j / 2,
//   Q(u)_j = sum_k F_jk (G_j - G_k) d / 6      (the Hermite part of u~)
//   Q^*(u)_j = sum_k (W_j + W_k) S_jk / 2,  W_i = T_i M_i / V_i,  T_i = sum_k F_ik (u_i - u_k) d^T
//   / 6
// (Q^* is the adjoint of Q through the gradient G_i = (1/V_i) sum_k (u_k - u_i) S^T M_i^T / 2).
// The product term above is a symmetric operator of the transported field, so it has no skew
// part and drops out. The split (skew-symmetric) form is how 4th-order centred schemes keep
// kinetic energy (Kuya, Totani & Kawai, J. Comput. Phys. 375, 823-853, 2018; Pirozzoli, Annu.
// Rev. Fluid Mech. 43, 163-194, 2011); with F the 4th-order projected flux S . u~ the two forms
// agree where sum_k F_jk + B_j = 0. Exactly energy-neutral for any F (round-off), the order
// it keeps is measured (validation/taylor_green).
//
// apply(u, conv), the flux form with the product term (the truncation tests' operator), is not
// energy-conserving: the Hermite term and the product term are not skew-symmetric, and the
// 4th-order mass flux u~.S is not the projection's divergence. Tried and not kept: subtracting
// u_j/2 times the divergence of that mass flux (the usual skew correction of collocated
// schemes; the truncation order stays 3.99) stops the no-model TGV Re 1600 from blowing up at
// 48^3 (max -dE/dt error 0.27 of the peak), but with sigma at 64^3 it moves the peak from
// -1.1 % to -6.1 % (bench_tgv_re1600, validation/tgv_les), so the LES case would fail.
//
// Form::deconvolution (the architecture text taken literally; kept to measure it):
//   phi_j  = ubar_j - G_j m1_j / V_j - 1/2 H_j : M2_j / V_j
//            (m1 = int (x - x_j) dV: O(h) on non-centred duals, 0 on symmetric ones;
//             M2 = int (x - x_j)(x - x_j)^T dV: the O(h^2) term; the third-moment term is O(h^3),
//             LocalMesh has no third moments and it vanishes on symmetric duals; H = G(G))
//   phi_jk = (phi_j + phi_k)/2 + d . (G phi_j - G phi_k) / 8,  F_jk = (phi_jk . S) phi_jk
// With the midpoint face rule this is 4th order only for fields that vary along one axis;
// for 2D/3D fields it is 2nd order (measured in tests/flow/test_convection_central4.cpp).
//
// Ghost layers: the gradients at layer-1 ghosts are computed locally from layer-2 values
// (one loop over all local edges instead of a halo exchange of 9 values per node), so the
// mesh must carry at least 2 ghost layers; the constructor refuses fewer. Allocation-free
// after construction once `conv` has the mesh's size.
#pragma once

#include <array>

#include "flow/convection_scheme.hpp"

namespace valsalva::flow {

class ConvectionCentral4 final : public ConvectionScheme {
 public:
  enum class Form { edge4, deconvolution };

  explicit ConvectionCentral4(const mesh::LocalMesh& mesh, Form form = Form::edge4);
  void apply(const VectorField& u, VectorField& conv) override;
  // The skew-symmetric form (edge4 only; the deconvolution form throws std::logic_error).
  void apply(const VectorField& u, const EdgeField& flux, VectorField& conv) override;
  std::string name() const override {
    return form_ == Form::edge4 ? "central4" : "central4_deconvolution";
  }

 private:
  void deconvolve(const VectorField& u);  // nodal_ from u (owned, then halo-inserted)

  const mesh::LocalMesh& mesh_;
  Form form_;
  TensorField grad_;
  TensorField adjoint_;                                  // T_i, then W_i, of the skew form
  VectorField nodal_;                                    // deconvolution form: point values
  std::vector<std::array<Eigen::Matrix3d, 3>> hessian_;  // per component, deconvolution form
};

}  // namespace valsalva::flow
