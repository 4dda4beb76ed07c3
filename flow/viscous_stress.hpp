// Viscous term in full-stress form with a variable nodal kinematic viscosity, per unit volume:
//   out_j = (1/V_j) [ sum_k F_jk + sum_faces nu_j (G_j + G_j^T) A_j ],
//   F_jk  = nu_jk [ a_jk (v_k - v_j) + Gbar_jk (S_jk - a_jk d_jk) + Gbar_jk^T S_jk ],
//   Gbar_jk = (G_j + G_k)/2,  nu_jk = (nu_j + nu_k)/2,
// the edge-based discretisation of div( nu (grad v + grad v^T) ) on the median dual (Barth, VKI
// LS 1994-05; the grad v part is flow::viscous(): compact two-point flux plus the non-orthogonal
// correction, exact for linear fields; the transpose part uses the averaged nodal gradient).
//
// Edge viscosity = arithmetic mean of the two ends: second-order accurate for a smooth nu (as
// nu_sgs from a resolved gradient is), symmetric in j and k so that F_kj = -F_jk and momentum is
// conserved edge by edge, positive whenever both ends are, and cheap. A harmonic mean is the
// choice for coefficients that jump across material interfaces, which nu + nu_sgs does not do.
//
// With constant nu the transpose part is nu grad(div v) in the continuum. Discretely it is the
// divergence of the nodal gradient's columns; on uniform periodic meshes gradient and
// divergence are commuting difference operators, so it vanishes to round-off when the discrete
// divergence does, and viscous_stress() equals nu * viscous() (tests/flow/test_viscous_stress).
#pragma once

#include <vector>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

// `weights`: flow::laplacian_weights(mesh); `nu`: nodal kinematic viscosity (m^2/s) with valid
// ghost values; `grad`: the gradient of v from flow::gradient() ((i, j) = d v_i / d x_j).
// Owned and ghost values of `out` are valid on return.
void viscous_stress(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                    const ScalarField& nu, const VectorField& v, const TensorField& grad,
                    VectorField& out);

}  // namespace valsalva::flow
