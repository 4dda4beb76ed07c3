#include "les/spectrum_rescale.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "les/fft_box.hpp"

namespace valsalva::les {

void rescale_to_spectrum(const std::function<double(double)>& spectrum, int n, double length,
                         std::span<double> u, std::span<double> v, std::span<double> w) {
  check_box_fields("rescale_to_spectrum", n, u.size(), v.size(), w.size());
  FftBox box(n);
  const std::array<std::span<double>, 3> comps{u, v, w};
  std::array<std::vector<std::complex<double>>, 3> hat;
  for (int c = 0; c < 3; ++c) {
    std::copy(comps[c].begin(), comps[c].end(), box.real().begin());
    box.forward();
    hat[c].assign(box.spectrum().begin(), box.spectrum().end());
  }
  const int smax = n / 2 - 1;
  auto shell_of = [](int mx, int my, int mz) {
    return static_cast<int>(std::lround(std::sqrt(double(mx * mx + my * my + mz * mz))));
  };
  std::vector<double> shell_energy(smax + 1, 0.0), scale(smax + 1, 0.0);
  for_each_mode(box, [&](std::size_t i, int mx, int my, int mz, double mult) {
    const int s = shell_of(mx, my, mz);
    if (s >= 1 && s <= smax)
      shell_energy[s] +=
          0.5 * mult * (std::norm(hat[0][i]) + std::norm(hat[1][i]) + std::norm(hat[2][i]));
  });
  const double dk = 2.0 * std::numbers::pi / length;
  for (int s = 1; s <= smax; ++s) {
    if (!(shell_energy[s] > 0.0))
      throw std::invalid_argument(fmt::format(
          "rescale_to_spectrum: shell {} (k = {} 1/m) has no energy to rescale", s, s * dk));
    scale[s] = std::sqrt(spectrum(s * dk) * dk / shell_energy[s]);
  }
  for_each_mode(box, [&](std::size_t i, int mx, int my, int mz, double) {
    const int s = shell_of(mx, my, mz);
    const double f = (s >= 1 && s <= smax) ? scale[s] : 0.0;
    for (auto& h : hat) h[i] *= f;
  });
  for (int c = 0; c < 3; ++c) {
    std::copy(hat[c].begin(), hat[c].end(), box.spectrum().begin());
    box.backward();
    std::copy(box.real().begin(), box.real().end(), comps[c].begin());
  }
}

}  // namespace valsalva::les
