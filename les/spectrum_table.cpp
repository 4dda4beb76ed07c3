#include "les/spectrum_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace valsalva::les {

SpectrumTable::SpectrumTable(std::vector<double> k, std::vector<double> E,
                             Extrapolation extrapolation, std::string source)
    : k_(std::move(k)),
      E_(std::move(E)),
      extrapolation_(extrapolation),
      source_(std::move(source)) {
  if (k_.size() != E_.size() || k_.size() < 2)
    throw std::invalid_argument(
        fmt::format("{}: spectrum table needs >= 2 (k, E) pairs, got {} k "
                    "and {} E values",
                    source_, k_.size(), E_.size()));
  for (std::size_t i = 0; i < k_.size(); ++i) {
    if (!(k_[i] > 0.0) || !(E_[i] > 0.0) || !std::isfinite(k_[i]) || !std::isfinite(E_[i]))
      throw std::invalid_argument(
          fmt::format("{}: point {} (k = {}, E = {}): k and E must be finite and > 0 for log-log "
                      "interpolation",
                      source_, i, k_[i], E_[i]));
    if (i > 0 && !(k_[i] > k_[i - 1]))
      throw std::invalid_argument(
          fmt::format("{}: k must increase strictly, but k[{}] = {} after "
                      "k[{}] = {}",
                      source_, i, k_[i], i - 1, k_[i - 1]));
    logk_.push_back(std::log(k_[i]));
    logE_.push_back(std::log(E_[i]));
  }
}

double SpectrumTable::operator()(double k) const {
  if (!(k > 0.0))
    throw std::invalid_argument(fmt::format("{}: E(k) needs k > 0, got {}", source_, k));
  if ((k < k_.front() || k > k_.back()) && extrapolation_ == Extrapolation::none)
    throw std::out_of_range(fmt::format("{}: k = {} outside the table range [{}, {}]", source_, k,
                                        k_.front(), k_.back()));
  const double lk = std::log(k);
  // Segment i: [k_i, k_i+1], clamped to the end segments (power-law extrapolation).
  const auto it = std::upper_bound(logk_.begin(), logk_.end(), lk);
  std::size_t i = it == logk_.begin() ? 0 : static_cast<std::size_t>(it - logk_.begin()) - 1;
  i = std::min(i, logk_.size() - 2);
  const double t = (lk - logk_[i]) / (logk_[i + 1] - logk_[i]);
  return std::exp(logE_[i] + t * (logE_[i + 1] - logE_[i]));
}

double table_moment(const SpectrumTable& E, double p) {
  const auto& k = E.k();
  const auto& e = E.E();
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    // On the segment E = e_i (k / k_i)^a, so k^p E integrates to a power of exponent a + p + 1.
    const double ratio = k[i + 1] / k[i];
    const double a = std::log(e[i + 1] / e[i]) / std::log(ratio), q = a + p + 1.0;
    const double base = e[i] * std::pow(k[i], p + 1.0);
    sum += std::abs(q) < 1e-12 ? base * std::log(ratio) : base * (std::pow(ratio, q) - 1.0) / q;
  }
  return sum;
}

LargeScales large_scales(const SpectrumTable& E) {
  LargeScales s;
  s.energy = table_moment(E, 0.0);
  const double u2 = 2.0 * s.energy / 3.0;
  s.u_rms = std::sqrt(u2);
  s.integral_length = std::numbers::pi / (2.0 * u2) * table_moment(E, -1.0);
  s.turnover_time = s.integral_length / s.u_rms;
  return s;
}

}  // namespace valsalva::les
