// Womersley flow in a rigid circular pipe (Womersley, J. Physiol. 127, 553-563, 1955): the
// exact axial velocity for a flow rate Q(t) = Q0 + Re[Qh exp(i w t)],
//   u(r, t) = 2 Q0 / (pi R^2) (1 - r^2/R^2)
//           + Re[ Qh / (pi R^2) (1 - J0(L r/R) / J0(L)) / (1 - 2 J1(L) / (L J0(L))) e^{i w t} ],
//   L = i^{3/2} Wo,  Wo = R sqrt(w / nu),
// whose flux over the disc is exactly Q(t) (int_0^1 2 s J0(L s) ds = 2 J1(L) / L).
// A sine waveform mean + A sin(w t + phi) has Qh = -i A e^{i phi}.
// Complex Bessel functions J0, J1: ascending power series for |z| < 18 (at |z| = 18 on the
// Womersley ray arg z = 3 pi / 4 the largest term exceeds |J0| by about 10^2.4, so ~13 digits
// survive) and Hankel's asymptotic expansion beyond (Abramowitz & Stegun 9.2.5-9.2.10; its
// smallest term there is ~exp(-2|z|) < 1e-15), so Wo up to 20 and beyond is evaluated to
// ~1e-13 relative.
#pragma once

#include <complex>

namespace valsalva::flow {

std::complex<double> bessel_j0(std::complex<double> z);
std::complex<double> bessel_j1(std::complex<double> z);

struct Womersley {
  double radius = 1;                    // m
  double nu = 1;                        // kinematic viscosity, m^2/s
  double omega = 1;                     // angular frequency, rad/s
  double mean = 0;                      // Q0, m^3/s
  std::complex<double> harmonic{0, 0};  // Qh, m^3/s

  // From a sine flow rate mean + amplitude sin(2 pi t / period + phase).
  static Womersley from_sine(double radius, double nu, double mean, double amplitude, double period,
                             double phase);
  double womersley_number() const;
  // Axial velocity at distance r from the axis (r <= radius), m/s.
  double velocity(double r, double t) const;
  // The driving kinematic pressure gradient G(t) = -(1/rho) dp/dz, m/s^2, with which u solves
  // du/dt = G + nu (u'' + u'/r): G = 8 nu Q0 / (pi R^4) + Re[G_h e^{i w t}],
  // G_h = i w Qh / (pi R^2 (1 - 2 J1(L) / (L J0(L)))) (the flux of the oscillating profile).
  double pressure_gradient(double t) const;
};

}  // namespace valsalva::flow
