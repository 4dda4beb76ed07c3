// Edge weights w_jk of the compact Poisson operator sum_k w_jk (x_k - x_j) for
// flow::PressurePoisson. On all-tetrahedral meshes w_jk = -sum_T V_T grad N_j . grad N_k, the
// P1 finite-element stiffness, which the median-dual finite-volume Laplacian equals (Barth,
// VKI LS 1994-05, sec. 3) and which is consistent on any tetrahedral mesh; the two-point weight
// |S|^2/(S.d) is NOT consistent where S_jk is not parallel to d_jk (the measured error on split
// tetrahedra does not decrease with h). On other meshes the two-point weight is used: exact on
// uniform hexahedra, where S_jk || d_jk; mixed and perturbed hexahedral meshes are a known
// limitation.
#pragma once

#include <vector>

#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::flow {

std::vector<double> poisson_weights(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                                    const mesh::LocalMesh& local);

// The same on meshes of tetrahedra and right prisms (extruded slabs): on a prism (a0 a1 a2
// below b0 b1 b2) the tensor product of the section triangle's P1 stiffness with the lumped 1D
// mass along the axis plus the lumped section mass with the 1D stiffness, K_2D (x) M_1D +
// M_2D (x) K_1D: in-plane edges h/2 cot(theta_opposite)/2, axial edges A/(3 h), nothing on the
// quad diagonals (not edges). Compact, exact for linear fields, and on a z-invariant field the
// section's P1 operator times h. Throws std::invalid_argument for other cell types or a prism
// whose top is not its bottom translated (relative mismatch above 1e-9).
std::vector<double> slab_stiffness_weights(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                                           const mesh::LocalMesh& local);

}  // namespace valsalva::flow
