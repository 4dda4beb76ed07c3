#include "les/energy_spectrum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "les/fft_box.hpp"

namespace valsalva::les {

namespace {
using Spectra = std::array<std::vector<std::complex<double>>, 3>;

Spectra transform(std::span<const double> u, std::span<const double> v, std::span<const double> w,
                  FftBox& box) {
  Spectra hat;
  const std::array<std::span<const double>, 3> comps{u, v, w};
  for (int c = 0; c < 3; ++c) {
    std::copy(comps[c].begin(), comps[c].end(), box.real().begin());
    box.forward();
    hat[c].assign(box.spectrum().begin(), box.spectrum().end());
  }
  return hat;
}
}  // namespace

double EnergySpectrum::total() const {
  double s = 0.0;
  for (double e : E) s += e * dk;
  return s;
}

EnergySpectrum energy_spectrum(std::span<const double> u, std::span<const double> v,
                               std::span<const double> w, int n, double length) {
  check_box_fields("energy_spectrum", n, u.size(), v.size(), w.size());
  if (!(length > 0.0)) throw std::invalid_argument("energy_spectrum: box length must be > 0");
  FftBox box(n);
  const Spectra hat = transform(u, v, w, box);
  EnergySpectrum s;
  s.dk = 2.0 * std::numbers::pi / length;
  const int shells = static_cast<int>(std::lround(std::sqrt(3.0) * n / 2)) + 1;
  s.E.assign(shells, 0.0);
  for_each_mode(box, [&](std::size_t i, int mx, int my, int mz, double mult) {
    const int shell = static_cast<int>(std::lround(std::sqrt(double(mx * mx + my * my + mz * mz))));
    s.E[shell] += 0.5 * mult * (std::norm(hat[0][i]) + std::norm(hat[1][i]) + std::norm(hat[2][i]));
  });
  s.k.resize(shells);
  for (int i = 0; i < shells; ++i) {
    s.k[i] = i * s.dk;
    s.E[i] /= s.dk;
  }
  return s;
}

double spectral_divergence_ratio(std::span<const double> u, std::span<const double> v,
                                 std::span<const double> w, int n, double length) {
  check_box_fields("spectral_divergence_ratio", n, u.size(), v.size(), w.size());
  FftBox box(n);
  const Spectra hat = transform(u, v, w, box);
  const double dk = 2.0 * std::numbers::pi / length;
  double div2 = 0.0, grad2 = 0.0;
  for_each_mode(box, [&](std::size_t i, int mx, int my, int mz, double mult) {
    const double kx = mx * dk, ky = my * dk, kz = mz * dk;
    div2 += mult * std::norm(kx * hat[0][i] + ky * hat[1][i] + kz * hat[2][i]);
    grad2 += mult * (kx * kx + ky * ky + kz * kz) *
             (std::norm(hat[0][i]) + std::norm(hat[1][i]) + std::norm(hat[2][i]));
  });
  return grad2 > 0.0 ? std::sqrt(div2 / grad2) : 0.0;
}

}  // namespace valsalva::les
