// Fully developed pulsatile pipe flow of a generalised-Newtonian fluid in 1D, the reference of
// validation/womersley_rheology. In a straight rigid pipe driven by a uniform kinematic pressure
// gradient G(t) = -(1/rho) dp/dz the axial velocity u(r, t) alone obeys
//   du/dt = G(t) + (1/r) d/dr (r nu(|du/dr|) du/dr),   du/dr(0) = 0,  u(R) = 0,
// with nu = mu(gamma_dot) / rho and gamma_dot = |du/dr| (the only strain rate of this flow).
// Vertex-centred finite volumes on r_i = i R / N (the axis node's volume r^2/2 over [0, dr/2]),
// the face viscosity from the face's shear rate, Crank-Nicolson in time with the viscosity of
// the extrapolated half-step velocity 3/2 u^n - 1/2 u^(n-1) (second order in dt and dr; the
// tridiagonal system solved by the Thomas algorithm). With a Newtonian model it reproduces
// Womersley's solution (checked by the case).
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "flow/viscosity_model.hpp"
#include "validation/non_newtonian_pipe/radial_reference.hpp"

namespace valsalva::validation {

struct PulsatilePipe {
  flow::ViscosityModel model;
  double density = 0;                      // kg/m3
  double radius = 0;                       // m
  double period = 0;                       // s
  std::function<double(double)> gradient;  // G(t), m/s2
};

struct PulsatileHistory {
  std::vector<double> time, flow_rate, wall_shear;  // samples of the last period, both ends
  RadialProfile start;      // u(r_i), i = 0 .. N, at the start of the last period (t = k T)
  double cycle_change = 0;  // max_i |u_i(kT) - u_i((k-1)T)| / max |u| over the last period
};

// Runs `periods` periods from rest on `cells` radial intervals, `steps` steps per period. The
// wall shear stress tau_w = -mu(gamma_w) du/dr(R) (positive for forward flow) with the
// one-sided second-order derivative (3 u_N - 4 u_(N-1) + u_(N-2)) / (2 dr).
PulsatileHistory pulsatile_pipe(const PulsatilePipe& pipe, int periods, int cells, int steps);

// One period of a signal sampled at increasing times covering [t0, t0 + T]: mean, first
// harmonic f ~ mean + amplitude sin(w (t - t0) + phase), min, max, mean |f| and
// OSI = 1/2 (1 - |mean f| / mean |f|) (for a wall shear stress, TAWSS and OSI of Ku et al.
// 1985). Linear interpolation onto 4096 uniform points, then the periodic trapezoidal rule.
struct CycleSummary {
  double mean = 0, amplitude = 0, phase = 0, min = 0, max = 0, mean_abs = 0, osi = 0;
};
CycleSummary cycle_summary(const std::vector<double>& time, const std::vector<double>& value,
                           double t0, double period);

}  // namespace valsalva::validation
