// Complex Bessel functions and the Womersley profile; see womersley.hpp for the formulas.
#include "flow/womersley.hpp"

#include <cmath>
#include <numbers>

namespace valsalva::flow {

namespace {

using C = std::complex<double>;
constexpr double switch_radius = 18.0;

// J_nu(z) = (z/2)^nu sum_k (-z^2/4)^k / (k! (k + nu)!), nu = 0, 1.
C series(int nu, C z) {
  const C q = -0.25 * z * z;
  C term = nu == 0 ? C(1) : 0.5 * z;
  C sum = term;
  for (int k = 1; k < 200; ++k) {
    term *= q / (double(k) * double(k + nu));
    sum += term;
    if (std::abs(term) < 1e-17 * std::abs(sum)) break;
  }
  return sum;
}

// Hankel: J_nu(z) = sqrt(2/(pi z)) (P cos chi - Q sin chi), chi = z - nu pi/2 - pi/4,
// P = sum_k (-1)^k a_2k / z^2k, Q = sum_k (-1)^k a_2k+1 / z^2k+1,
// a_k = prod_{m=1..k} (4 nu^2 - (2m - 1)^2) / (k! 8^k). Summed while the terms decrease.
C hankel(int nu, C z) {
  const double mu = 4.0 * nu * nu;
  C p = 1, q = 0, term = 1;
  double last = INFINITY;
  for (int k = 1; k < 200; ++k) {
    term *= (mu - double(2 * k - 1) * (2 * k - 1)) / (8.0 * k) / z;
    const double size = std::abs(term);
    if (size >= last) break;
    last = size;
    // term = a_k / z^k; the sign (-1)^floor(k/2) goes with P (even k) or Q (odd k).
    const double sign = ((k / 2) % 2 == 0) ? 1.0 : -1.0;
    if (k % 2 == 0)
      p += sign * term;
    else
      q += sign * term;
    if (size < 1e-17) break;
  }
  const C chi = z - (nu * 0.5 + 0.25) * std::numbers::pi;
  return std::sqrt(2.0 / (std::numbers::pi * z)) * (p * std::cos(chi) - q * std::sin(chi));
}

C bessel(int nu, C z) {
  // Hankel's expansion holds for |arg z| < pi; J0 is even and J1 odd, so use Re z >= 0.
  if (std::abs(z) < switch_radius) return series(nu, z);
  if (z.real() < 0) return (nu == 0 ? 1.0 : -1.0) * hankel(nu, -z);
  return hankel(nu, z);
}

}  // namespace

std::complex<double> bessel_j0(std::complex<double> z) {
  return bessel(0, z);
}
std::complex<double> bessel_j1(std::complex<double> z) {
  return bessel(1, z);
}

Womersley Womersley::from_sine(double radius, double nu, double mean, double amplitude,
                               double period, double phase) {
  Womersley w;
  w.radius = radius;
  w.nu = nu;
  w.omega = 2 * std::numbers::pi / period;
  w.mean = mean;
  // A sin(w t + phi) = Re[-i A e^{i phi} e^{i w t}].
  w.harmonic = C(0, -amplitude) * std::polar(1.0, phase);
  return w;
}

double Womersley::womersley_number() const {
  return radius * std::sqrt(omega / nu);
}

double Womersley::velocity(double r, double t) const {
  const double area = std::numbers::pi * radius * radius;
  const double s = r / radius;
  double u = 2 * mean / area * (1 - s * s);
  if (harmonic != C(0) && omega > 0) {
    const C lambda = std::polar(womersley_number(), 0.75 * std::numbers::pi);  // i^{3/2} Wo
    const C j0 = bessel_j0(lambda);
    const C shape =
        (1.0 - bessel_j0(lambda * s) / j0) / (1.0 - 2.0 * bessel_j1(lambda) / (lambda * j0));
    u += (harmonic / area * shape * std::polar(1.0, omega * t)).real();
  }
  return u;
}

double Womersley::pressure_gradient(double t) const {
  const double area = std::numbers::pi * radius * radius;
  double g = 8 * nu * mean / (area * radius * radius);
  if (harmonic != C(0) && omega > 0) {
    const C lambda = std::polar(womersley_number(), 0.75 * std::numbers::pi);
    const C factor = 1.0 - 2.0 * bessel_j1(lambda) / (lambda * bessel_j0(lambda));
    g += (C(0, omega) * harmonic / (area * factor) * std::polar(1.0, omega * t)).real();
  }
  return g;
}

}  // namespace valsalva::flow
