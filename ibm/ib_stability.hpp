// Time-step bound of the explicit immersed-boundary coupling with solid inertia neglected.
// Linearised about a state at rest, a force F on the markers accelerates the fluid at the
// nodes by f/rho, and the markers move with the interpolated velocity, so
//   d^2 X / dt^2 = -(1/rho) A K X,   A = Interp * Spread (A_ab = sum_j phi_ja phi_jb V_j [1/m^3]),
// K = -dF/dX the solid (+ tether + contact) stiffness; contact enters as the penalty springs of a
// fully closed contact on every contact-surface node (ibm/immersed_body.hpp), so that the bound
// holds when surfaces meet between two evaluations. The coupling is an oscillator with
//   omega^2 = lambda_max(A K) / rho
// (A K is similar to the symmetric A^1/2 K A^1/2, so lambda is real and >= 0 for stable solids).
// The scheme's stability interval on the imaginary axis then bounds dt:
//   per_stage (RK4 stages on the pair (u, X)):          dt <= 2 sqrt(2) / omega
//   per_step  (force held, X moved by u^{n+1}: symplectic Euler): dt <= 2 / omega.
// Neglected: the projection (it removes the compressive part of the fluid response, which only
// lowers the eigenvalue) and viscosity (damping moves the eigenvalues off the imaginary axis
// towards the real axis, where the bound is at least as wide); the bound is therefore safe and,
// for modes that the projection does not touch, sharp (measured in tests/ibm/test_ib_stability).
// In the Peskin picture, A ~ c / h^3 for smooth modes, so dt ~ sqrt(rho h^3 / (c k)) with k the
// effective spring between markers one kernel width apart: dt grows as h^(3/2) / sqrt(stiffness).
// lambda_max is found by power iteration on v -> A K v (spread and interpolate of the actual
// kernel, so mesh, kernel width and RKPM correction are all included).
#pragma once

#include <Eigen/Core>
#include <functional>

#include "ibm/dirac_transfer.hpp"

namespace valsalva::ibm {

struct StiffnessEigenvalue {
  double lambda = 0;  // lambda_max(A K) [N/m^4]
  int iterations = 0;
  double change = 0;  // relative change of the last iteration
};

// Power iteration on A K with the markers already located in `transfer`; `apply_stiffness`
// computes K v for a 3 x markers array (replicated). Collective; result identical on all ranks.
StiffnessEigenvalue kernel_mapped_stiffness_eigenvalue(
    DiracTransfer& transfer,
    const std::function<void(const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&)>& apply_stiffness,
    int max_iterations = 200, double tolerance = 1e-5);

// The bound above: factor / sqrt(lambda / rho), factor 2 sqrt(2) (per stage) or 2 (per step).
double coupling_time_step_bound(double lambda, double fluid_density, bool per_stage);

}  // namespace valsalva::ibm
