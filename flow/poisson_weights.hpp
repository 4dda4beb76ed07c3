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

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/mesh.hpp"

namespace valsalva::flow {

std::vector<double> poisson_weights(const Mesh& mesh, const DualMetrics& metrics,
                                    const LocalMesh& local);

}  // namespace valsalva::flow
