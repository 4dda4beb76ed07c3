#include "les/random_field.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "les/fft_box.hpp"

namespace valsalva::les {

void random_solenoidal_field(const std::function<double(double)>& spectrum, int n, double length,
                             std::uint64_t seed, std::span<double> u, std::span<double> v,
                             std::span<double> w, Amplitudes amplitudes) {
  check_box_fields("random_solenoidal_field", n, u.size(), v.size(), w.size());
  if (!(length > 0.0))
    throw std::invalid_argument(fmt::format("random_solenoidal_field: box length {} <= 0", length));
  FftBox box(n);
  const double dk = 2.0 * std::numbers::pi / length;
  const int smax = n / 2 - 1;
  auto shell_of = [](int mx, int my, int mz) {
    return static_cast<int>(std::lround(std::sqrt(double(mx * mx + my * my + mz * mz))));
  };

  // White noise -> Fourier coefficients, one component at a time (seeded, reproducible).
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::array<std::vector<std::complex<double>>, 3> hat;
  for (auto& h : hat) {
    for (double& x : box.real()) x = normal(rng);
    box.forward();
    h.assign(box.spectrum().begin(), box.spectrum().end());
  }

  // Modes per shell (full spectrum) and amplitudes.
  std::vector<double> modes(smax + 1, 0.0), amplitude(smax + 1, 0.0);
  for_each_mode(box, [&](std::size_t, int mx, int my, int mz, double mult) {
    const int s = shell_of(mx, my, mz);
    if (s >= 1 && s <= smax) modes[s] += mult;
  });
  for (int s = 1; s <= smax; ++s) {
    const double e = spectrum(s * dk);
    if (!(e >= 0.0) || !std::isfinite(e))
      throw std::invalid_argument(fmt::format(
          "random_solenoidal_field: prescribed E(k = {} 1/m) = {} is not a finite value >= 0",
          s * dk, e));
    amplitude[s] = std::sqrt(2.0 * e * dk / modes[s]);
  }

  // White noise normalised by 1/n^3 has <|r_hat_c|^2> = 1/n^3; P keeps 2 of 3 components.
  const double gaussian_scale = std::sqrt(0.5 * static_cast<double>(box.real_size()));
  for_each_mode(box, [&](std::size_t i, int mx, int my, int mz, double) {
    const int s = shell_of(mx, my, mz);
    if (s < 1 || s > smax) {
      for (auto& h : hat) h[i] = 0.0;
      return;
    }
    const std::array<double, 3> k{double(mx), double(my), double(mz)};
    const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    const std::complex<double> kr = (k[0] * hat[0][i] + k[1] * hat[1][i] + k[2] * hat[2][i]) / k2;
    double norm2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      hat[c][i] -= k[c] * kr;
      norm2 += std::norm(hat[c][i]);
    }
    double scale = amplitude[s] * gaussian_scale;
    if (amplitudes == Amplitudes::fixed)
      scale = norm2 > 0.0 ? amplitude[s] / std::sqrt(norm2) : 0.0;
    for (auto& h : hat) h[i] *= scale;
  });

  const std::array<std::span<double>, 3> out{u, v, w};
  for (int c = 0; c < 3; ++c) {
    std::copy(hat[c].begin(), hat[c].end(), box.spectrum().begin());
    box.backward();
    std::copy(box.real().begin(), box.real().end(), out[c].begin());
  }
}

}  // namespace valsalva::les
