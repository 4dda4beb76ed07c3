#include "analysis/uniform_sampling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace valsalva::analysis {

Sampling check_sampling(std::span<const double> t, const std::string& what, double tolerance) {
  if (t.size() < 2)
    throw std::invalid_argument(
        fmt::format("{}: {} time samples, at least 2 needed", what, t.size()));
  Sampling s;
  s.dt_min = INFINITY, s.dt_max = -INFINITY;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double dt = t[i] - t[i - 1];
    if (!std::isfinite(t[i]) || !std::isfinite(t[i - 1]) || !(dt > 0))
      throw std::invalid_argument(fmt::format(
          "{}: time is not strictly increasing at sample {} (t = {:.17g} s after {:.17g} s)", what,
          i, t[i], t[i - 1]));
    s.dt_min = std::min(s.dt_min, dt), s.dt_max = std::max(s.dt_max, dt);
  }
  s.dt_mean = (t.back() - t.front()) / double(t.size() - 1);
  s.uniform = s.dt_max - s.dt_min <= tolerance * s.dt_mean;
  return s;
}

std::vector<double> resample_uniform(std::span<const double> t, std::span<const double> v,
                                     std::size_t n) {
  if (t.size() != v.size() || t.size() < 2 || n < 2)
    throw std::invalid_argument(
        fmt::format("resample_uniform: {} times, {} values, {} samples (need equal sizes >= 2)",
                    t.size(), v.size(), n));
  std::vector<double> out(n);
  std::size_t j = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double tk =
        k + 1 == n ? t.back() : t.front() + double(k) * (t.back() - t.front()) / double(n - 1);
    while (j + 2 < t.size() && t[j + 1] < tk) ++j;
    const double w = (tk - t[j]) / (t[j + 1] - t[j]);
    out[k] = (1 - w) * v[j] + w * v[j + 1];
  }
  return out;
}

}  // namespace valsalva::analysis
