// 3D energy spectrum E(k) of a velocity field on a periodic n^3 box of side L (layout in
// fft_box.hpp), binned in spherical shells of width dk = 2 pi / L centred on k_s = s dk
// (s = round(|m|), m the integer wavenumber). Normalised so that
//   sum_s E(k_s) dk = 1/2 <u.u>   (Parseval; every mode counted, including the corners),
// the usual discrete definition (e.g. Pope, Turbulent Flows, 2000, Sec. 6.4).
#pragma once

#include <span>
#include <vector>

namespace valsalva::les {

struct EnergySpectrum {
  double dk = 0.0;        // shell width 2 pi / L [1/m]
  std::vector<double> k;  // shell centres s dk, s = 0 .. [1/m]
  std::vector<double> E;  // [m^3/s^2]
  double total() const;   // sum E dk = 1/2 <u.u> [m^2/s^2]
};

EnergySpectrum energy_spectrum(std::span<const double> u, std::span<const double> v,
                               std::span<const double> w, int n, double length);

// Spectral divergence relative to the gradient magnitude:
//   sqrt(sum |k.u_hat|^2) / sqrt(sum |k|^2 |u_hat|^2), 0 for a solenoidal field.
double spectral_divergence_ratio(std::span<const double> u, std::span<const double> v,
                                 std::span<const double> w, int n, double length);

}  // namespace valsalva::les
