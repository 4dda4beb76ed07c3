#include "analysis/valve_cycles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace valsalva::analysis {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// int max(sign * Q, 0) dt between samples a and b (trapezoid, the zero crossing located
// linearly so that a sign change is split exactly).
double positive_part(const ValveSample& a, const ValveSample& b, double sign) {
  const double qa = sign * a.flow, qb = sign * b.flow, dt = b.time - a.time;
  if (qa >= 0 && qb >= 0) return 0.5 * (qa + qb) * dt;
  if (qa <= 0 && qb <= 0) return 0;
  const double theta = qa / (qa - qb);  // fraction of the interval before the crossing
  return qa > 0 ? 0.5 * qa * theta * dt : 0.5 * qb * (1 - theta) * dt;
}

}  // namespace

CycleSummary summarise_cycle(int cycle, std::span<const ValveSample> s,
                             const CycleOptions& options) {
  if (s.size() < 2)
    throw std::invalid_argument(
        fmt::format("valve cycle {}: {} samples, at least 2 are needed", cycle, s.size()));
  CycleSummary c;
  c.cycle = cycle;
  c.samples = static_cast<int>(s.size());
  c.start = options.start_time + cycle * options.period;
  c.end = c.start + options.period;
  c.tpg_max = c.tpg_min = nan;
  std::size_t peak = 0;
  double least = s.front().opening_ratio;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].flow > 0 && !(s[i].tpg <= c.tpg_max)) c.tpg_max = s[i].tpg;
    if (s[i].flow < 0 && !(s[i].tpg >= c.tpg_min)) c.tpg_min = s[i].tpg;
    if (s[i].opening_ratio > s[peak].opening_ratio) peak = i;
    least = std::min(least, s[i].opening_ratio);
    c.max_von_mises = std::max(c.max_von_mises, s[i].max_von_mises);
  }
  c.max_opening_ratio = s[peak].opening_ratio;
  c.min_opening_ratio = least;
  c.opening_start = c.fully_open = c.closing = nan;
  // Fractions of the swing from the closed orifice (not zero when the leaflets are held apart by
  // a contact clearance) to the largest opening.
  const double swing = c.max_opening_ratio - least;
  const double open = least + options.open_fraction * swing;
  const double full = least + options.full_fraction * swing;
  std::size_t closed_at = s.size();  // first sample of the closed phase
  if (swing > 0) {
    for (std::size_t i = 0; i <= peak; ++i)
      if (std::isnan(c.opening_start) && s[i].opening_ratio >= open) c.opening_start = s[i].time;
    for (std::size_t i = 0; i <= peak; ++i)
      if (std::isnan(c.fully_open) && s[i].opening_ratio >= full) c.fully_open = s[i].time;
    for (std::size_t i = peak; i < s.size(); ++i)
      if (s[i].opening_ratio <= open) {
        c.closing = s[i].time;
        closed_at = i;
        break;
      }
  }
  for (std::size_t i = 1; i < s.size(); ++i) {
    c.forward_volume += positive_part(s[i - 1], s[i], 1);
    const double back = positive_part(s[i - 1], s[i], -1);
    c.regurgitant_volume += back;
    (i <= closed_at ? c.closing_volume : c.leakage_volume) += back;
  }
  return c;
}

CycleTracker::CycleTracker(const CycleOptions& options) : options_(options) {
  if (!(options_.period > 0))
    throw std::invalid_argument(
        fmt::format("valve cycles: the period must be > 0 (got {})", options_.period));
}

int CycleTracker::cycle_of(double time) const {
  // A sample within round-off of a cycle boundary belongs to the cycle it starts.
  const double x = (time - options_.start_time) / options_.period;
  return static_cast<int>(std::floor(x + 1e-9));
}

std::optional<CycleSummary> CycleTracker::add(const ValveSample& s) {
  if (s.time < options_.start_time - 1e-9 * options_.period) return std::nullopt;
  std::optional<CycleSummary> done;
  if (!samples_.empty()) {
    const int open = cycle_of(samples_.front().time), now = cycle_of(s.time);
    if (now > open) {
      samples_.push_back(s);  // the boundary sample closes the open cycle
      if (samples_.size() >= 2) done = summarise_cycle(open, samples_, options_);
      samples_.clear();
    }
  }
  samples_.push_back(s);
  return done;
}

std::vector<double> CycleTracker::state() const {
  std::vector<double> flat;
  for (const auto& s : samples_)
    flat.insert(flat.end(), {s.time, s.flow, s.tpg, s.opening_ratio, s.max_von_mises});
  return flat;
}

void CycleTracker::restore(std::span<const double> flat) {
  if (flat.size() % valve_sample_fields != 0)
    throw std::invalid_argument(
        fmt::format("valve cycles: a checkpointed cycle of {} numbers is not whole samples of {}",
                    flat.size(), valve_sample_fields));
  samples_.clear();
  for (std::size_t i = 0; i < flat.size(); i += valve_sample_fields)
    samples_.push_back({flat[i], flat[i + 1], flat[i + 2], flat[i + 3], flat[i + 4]});
}

}  // namespace valsalva::analysis
