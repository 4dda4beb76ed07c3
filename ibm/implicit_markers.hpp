// The linearly implicit marker update of the immersed coupling (ImmersedOptions::mode =
// CouplingMode::implicit). With solid inertia neglected, the explicit coupling is an oscillator
// of frequency omega^2 = lambda_max(A K) / rho (ibm/ib_stability.hpp) whose bound, not the flow's
// CFL, sets the time step of stiff thin leaflets. Here the markers' displacement over a step
// solves the backward-Euler linearisation of the force,
//   (I + dt^2/rho A K) dX = dt U*,   A = Interp Spread at X^n, K = -dF/dX at X^n,
// with U* the fluid velocity interpolated at X^n after a flow step driven by the held force
//   F(X^n) - K dX^{n-1}
// (the force linearly extrapolated to the end of the step; dX^{n-1} is the previous step's
// displacement). The fluid response inside the solve is the unprojected one (A without the
// projection): that keeps the solve to spread-interpolate products. With the exact (projected)
// response this would be the backward-Euler force of Newren, Fogelson, Guy & Kirby,
// "Unconditionally stable discretizations of the immersed boundary equations", J. Comput. Phys.
// 222 (2007) 702; the unprojected Schur complement is the approximation Ceniceros, Fisher & Roma,
// J. Comput. Phys. 228 (2009) 7137, use to precondition theirs. This is ImplicitVariant::lagged
// (ibm/immersed_structure.hpp), the default. On the block of tests/ibm/test_implicit_coupling
// stretched by 1.2 it relaxes at 3.5 times the explicit per-stage bound, is marginal at 4x (the
// speed still 0.3 of its peak after 100 steps) and fails within 3 steps from 5x; with a 1.01
// stretch (the linear regime) it runs at every multiple up to 16x: the limit at the 1.2
// stretch is the linearisation of the force at X^n (K of the stretched block over one step's
// displacement), not the coupling. Newton iterations on the lagged equation
// dX = dt U* + dt^2/rho A [F(X^n + dX) - F(X^n)] (ImmersedOptions::implicit_newton_iterations;
// K re-assembled at each iterate, A kept at X^n, updates halved until the residual falls and no
// element inverts) move that limit from 4x to 5x; from 6x the Newton systems stop converging.
// ImplicitVariant::backward_euler (the projected A_P = Interp
// P Spread and the fluid's velocity and pressure corrected to the force F(X^n) - K dX; a
// pressure projection per product) relaxes at 3.5x, inverts an element in 3 steps at 4x, and
// runs up to 16x in the linear regime: no wider limit, for a projection per BiCGSTAB product.
// ImplicitVariant::consistent (rhs dt U* + c A K dX^{n-1}, the unprojected solve, the fluid
// uncorrected) is unstable from 2x even in the linear regime: the fluid keeps the response to
// -K dX^{n-1} while the markers move as if it had felt -K dX, and the "double count" of the
// lagged form is what damps that mismatch (a scalar model of one mode, with the fluid velocity
// at the marker as a state, shows the same: lagged and backward_euler stable for every dt,
// consistent growing once c A K > 1). Markers move by dX, not by dt times the final
// interpolated velocity: the slip is (modelled - projected response) times the stiff part of
// the motion (zero for backward_euler up to the solve tolerances). In a steady state U* = 0
// and the markers do not move, so a loaded closed valve stays where its load puts it.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "ibm/dirac_transfer.hpp"

namespace valsalva::ibm {

struct ImplicitSolve {
  Eigen::Matrix3Xd displacement;  // dX, 3 x markers
  int iterations = 0;
  double residual = 0;  // |b - M dX| / |b|
};

// Applies the discrete pressure projection P to a nodal field v in place: v -= grad q with
// lap q = div v (flow::ProjectionRK4::project); q (one value per local node) is the warm start
// on entry and the potential on return. Collective.
using Projector = std::function<void(std::vector<Eigen::Vector3d>&, std::vector<double>&)>;

// Solves (I + c A K) dX = b (c = dt^2 / rho) by BiCGSTAB without a matrix: A through the
// transfer's spread and interpolation at its located markers, K through `apply_stiffness`
// (3 x markers, replicated). Collective; the result is identical on all ranks. Throws when the
// solve does not reach `tolerance` in `max_iterations`. With `project` (non-null and set) A is
// the projected response Interp P Spread (one projection per product); `guess` (3 x markers)
// replaces the initial guess b.
ImplicitSolve implicit_marker_displacement(
    DiracTransfer& transfer,
    const std::function<void(const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&)>& apply_stiffness,
    const Eigen::Matrix3Xd& b, double c, double tolerance = 1e-8, int max_iterations = 1000,
    const Projector* project = nullptr, const Eigen::Matrix3Xd* guess = nullptr);

}  // namespace valsalva::ibm
