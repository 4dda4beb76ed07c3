// Per-step quantities of a flow run: the explicit-stability estimate that sets or checks the
// time step, kinetic energy, vorticity, and the guard that finds non-finite or runaway values.
//
// Stability of the RK4 predictor (the projection is unconditionally stable). Per node j, by
// Gershgorin's theorem on the edge operators of flow/operators.hpp:
//   convection  eigenvalues within |Im| <= rc_j = (1/(2 V_j)) sum_k |u_jk . S_jk|
//   viscous     eigenvalues within [-rv_j, 0], rv_j = (2 nu / V_j) sum_k a_jk
// (both are exact on uniform hexahedra: rc = sum_i |u_i|/h, rv = 12 nu/h^2). Classical RK4
// (and the 1/4, 1/3, 1/2, 1 stage form, the same polynomial for linear problems) is stable on
// the imaginary axis up to 2 sqrt 2 and on the negative real axis up to 2.7853; the segment
// between these two points lies inside its stability region (|R(z)| <= 1 checked numerically),
// so dt is stable when
//   sigma = dt max_j (rc_j / 2.8284 + rv_j / 2.7853) <= 1.
// With a nodal viscosity (non-Newtonian fluids, nu + nu_sgs of LES) the viscous row of node j is
// bounded by rv_j = (2 / V_j) sum_k a_jk (nu_j + nu_k) / 2 (the edge viscosity of
// flow/viscous_stress.hpp) and the Fourier number is max_j nubar_j dt / h_j^2 with nubar_j the
// |a_jk|-weighted mean of node j's edge viscosities: each node's own neighbourhood sets the bound.
#pragma once

#include <string>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

inline constexpr double rk4_imaginary_limit = 2.8284271247461903;  // 2 sqrt 2
inline constexpr double rk4_real_limit = 2.7852935634052820;

struct StabilityRates {
  double stability = 0;   // max_j (rc_j / 2.83 + rv_j / 2.79), 1/s: sigma = dt * stability
  double convective = 0;  // max_j |u_j| / h_j, 1/s: CFL = dt * convective
  double viscous = 0;     // max_j nu(bar)_j / h_j^2, 1/s: Fourier number = dt * viscous
};

// Collective. `weights` are flow::laplacian_weights(mesh), nu the kinematic viscosity;
// `scratch` is resized to 4 num_local() and reused (no allocation inside the time loop).
StabilityRates stability_rates(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                               double nu, const VectorField& u, std::vector<double>& scratch);
// The same with the kinematic viscosity `nu` of every local node (ghosts valid).
StabilityRates stability_rates(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                               const ScalarField& nu, const VectorField& u,
                               std::vector<double>& scratch);

// Collective: 1/2 rho sum_j V_j |u_j|^2 over owned nodes, J.
double kinetic_energy(const mesh::LocalMesh& mesh, double rho, const VectorField& u);

// Vorticity = curl u from the velocity gradient (i, j) = d u_i / d x_j.
void vorticity(const TensorField& grad, VectorField& omega);

// Q-criterion Q = 1/2 (|W|^2 - |S|^2) with S, W the symmetric and antisymmetric parts of the
// velocity gradient (Hunt, Wray & Moin, CTR Summer Program 1988): Q > 0 marks vortex cores, 1/s^2.
void q_criterion(const TensorField& grad, ScalarField& q);

// Collective. Empty when every owned velocity and pressure is finite and |u| <= velocity_limit;
// otherwise a diagnosis of the bad node with the lowest dual-node number (the same for every
// partition): the field, the value, the node number and position.
std::string find_bad_state(const mesh::LocalMesh& mesh, const VectorField& u, const ScalarField& p,
                           double velocity_limit);

}  // namespace valsalva::flow
