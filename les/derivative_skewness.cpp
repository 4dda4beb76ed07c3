#include "les/derivative_skewness.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "les/fft_box.hpp"

namespace valsalva::les {

double derivative_skewness(std::span<const double> u, std::span<const double> v,
                           std::span<const double> w, int n, double length) {
  check_box_fields("derivative_skewness", n, u.size(), v.size(), w.size());
  if (!(length > 0.0)) throw std::invalid_argument("derivative_skewness: box length must be > 0");
  FftBox box(n);
  const double dk = 2.0 * std::numbers::pi / length;
  const std::array<std::span<const double>, 3> comps{u, v, w};
  double m2 = 0.0, m3 = 0.0;
  for (int c = 0; c < 3; ++c) {
    std::copy(comps[c].begin(), comps[c].end(), box.real().begin());
    box.forward();
    auto hat = box.spectrum();
    for_each_mode(box, [&](std::size_t i, int mx, int my, int mz, double) {
      const int m = c == 0 ? mx : (c == 1 ? my : mz);
      // The Nyquist mode has no well-defined derivative (its sine part is unresolved).
      const bool nyquist = 2 * std::abs(m) == n;
      hat[i] *= nyquist ? 0.0 : std::complex<double>(0.0, m * dk);
    });
    box.backward();
    for (double g : box.real()) {
      m2 += g * g;
      m3 += g * g * g;
    }
  }
  const double count = 3.0 * static_cast<double>(box.real_size());
  m2 /= count;
  m3 /= count;
  return m2 > 0.0 ? m3 / std::pow(m2, 1.5) : 0.0;
}

}  // namespace valsalva::les
