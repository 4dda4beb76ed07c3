// Periodic statistics; see periodic_stats.hpp.
#include "validation/turek_hron_fsi/periodic_stats.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace valsalva::validation {

PeriodicStats window_stats(std::span<const double> t, std::span<const double> y, double t0,
                           double t1) {
  PeriodicStats s;
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) {
      lo = std::min(lo, y[i]);
      hi = std::max(hi, y[i]);
    }
  if (hi < lo) return s;
  s.mean = (hi + lo) / 2;
  s.amplitude = (hi - lo) / 2;
  s.t0 = t0;
  s.t1 = t1;
  return s;
}

PeriodicStats periodic_stats(std::span<const double> t, std::span<const double> y, double t_from) {
  const auto first =
      static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), t_from) - t.begin());
  if (t.size() < first + 3) return {};
  const auto range = window_stats(t, y, t_from, t.back());
  std::vector<double> up;
  for (std::size_t i = first + 1; i < t.size(); ++i) {
    const double a = y[i - 1] - range.mean, b = y[i] - range.mean;
    if (a < 0 && b >= 0) up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a));
  }
  if (up.size() < 2) return {};
  const auto n = up.size();
  PeriodicStats s = window_stats(t, y, up[n - 2], up[n - 1]);
  s.periods = static_cast<int>(n - 1);
  double sum = 0, sum2 = 0;
  for (std::size_t k = 1; k < n; ++k) {
    const double a = window_stats(t, y, up[k - 1], up[k]).amplitude;
    sum += a;
    sum2 += a * a;
  }
  s.amplitude_mean = sum / s.periods;
  s.amplitude_std =
      std::sqrt(std::max(0.0, sum2 / s.periods - s.amplitude_mean * s.amplitude_mean));
  s.frequency = static_cast<double>(n - 1) / (up[n - 1] - up[0]);
  return s;
}

}  // namespace valsalva::validation
