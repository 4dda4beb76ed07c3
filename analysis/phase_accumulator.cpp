#include "analysis/phase_accumulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <regex>
#include <stdexcept>

#include "core/allocation_limit.hpp"

namespace valsalva::analysis {

namespace {

// Index of the M2 entry of the pair (a, b), a, b in 0..3 (3 = p; p only with itself).
constexpr int m2_index(int a, int b) {
  if (a > b) std::swap(a, b);
  if (a == b) return a;               // uu vv ww pp
  if (a == 0) return b == 1 ? 4 : 5;  // uv uw
  return 6;                           // vw
}

}  // namespace

PhaseAccumulator::PhaseAccumulator(PhaseStatisticsOptions options, std::size_t points)
    : options_(std::move(options)), points_(points) {
  const auto& o = options_;
  if (o.bins < 1) throw std::invalid_argument(fmt::format("statistics: bins = {} < 1", o.bins));
  if (o.period < 0 || !std::isfinite(o.period) || (o.period == 0 && o.bins != 1))
    throw std::invalid_argument(fmt::format(
        "statistics: period = {} s with bins = {} (period 0 means a plain average, 1 bin)",
        o.period, o.bins));
  if (!(o.density > 0))
    throw std::invalid_argument(fmt::format("statistics: density = {} kg/m^3", o.density));
  if (!std::regex_match(o.name, std::regex("[A-Za-z0-9_]+")))
    throw std::invalid_argument(fmt::format("statistics: name '{}' is not [A-Za-z0-9_]+", o.name));
  core::check_allocation(
      fmt::format("statistics.{}.bins = {} on {} points of this rank", o.name, o.bins, points_),
      static_cast<double>(o.bins) * static_cast<double>(points_), per_node * sizeof(double));
  counts_.assign(o.bins, 0);
  data_.assign(std::size_t(o.bins) * points_ * per_node, 0.0);
}

double PhaseAccumulator::phase_time(int bin) const {
  return options_.period * (bin + 0.5) / options_.bins;
}

std::int64_t PhaseAccumulator::cycle_of(double time) const {
  if (options_.period == 0) return 0;
  return static_cast<std::int64_t>(std::floor((time - options_.start_time) / options_.period));
}

int PhaseAccumulator::bin_of(double time) const {
  if (options_.period == 0) return 0;
  const double cycles = (time - options_.start_time) / options_.period;
  const double phase = cycles - std::floor(cycles);  // [0, 1)
  return std::min(options_.bins - 1, static_cast<int>(phase * options_.bins));
}

void PhaseAccumulator::add_sample(int bin, std::int64_t cycle, std::span<const double> values) {
  if (bin < 0 || bin >= options_.bins || values.size() != points_ * 4)
    throw std::invalid_argument(fmt::format(
        "statistics: bad sample (bin {}, {} values for {} points)", bin, values.size(), points_));
  if (counts_total() == 0) first_cycle_ = last_cycle_ = cycle;
  first_cycle_ = std::min(first_cycle_, cycle);
  last_cycle_ = std::max(last_cycle_, cycle);
  const double inv_n = 1.0 / double(++counts_[bin]);
  for (std::size_t i = 0; i < points_; ++i) {
    double* m = data_.data() + offset(bin, int(i));
    double d[4], e[4];  // deviation from the old mean, from the new mean
    for (int q = 0; q < 4; ++q) {
      const double x = values[4 * i + q];
      d[q] = x - m[q];
      m[q] += d[q] * inv_n;
      e[q] = x - m[q];
    }
    double* m2 = m + 4;
    m2[0] += d[0] * e[0], m2[1] += d[1] * e[1], m2[2] += d[2] * e[2], m2[3] += d[3] * e[3];
    m2[4] += d[0] * e[1], m2[5] += d[0] * e[2], m2[6] += d[1] * e[2];
  }
}

void PhaseAccumulator::merge(const PhaseAccumulator& other) {
  if (other.points_ != points_ || other.options_.bins != options_.bins ||
      other.options_.period != options_.period)
    throw std::invalid_argument("statistics: merge of accumulators over other points or bins");
  if (other.counts_total() == 0) return;
  if (counts_total() == 0) {
    first_cycle_ = other.first_cycle_, last_cycle_ = other.last_cycle_;
  } else {
    first_cycle_ = std::min(first_cycle_, other.first_cycle_);
    last_cycle_ = std::max(last_cycle_, other.last_cycle_);
  }
  for (int b = 0; b < options_.bins; ++b) {
    const double na = double(counts_[b]), nb = double(other.counts_[b]), n = na + nb;
    if (nb == 0) continue;
    for (std::size_t i = 0; i < points_; ++i) {
      double* a = data_.data() + offset(b, int(i));
      const double* o = other.data_.data() + other.offset(b, int(i));
      double delta[4];
      for (int q = 0; q < 4; ++q) delta[q] = o[q] - a[q];
      const double w = na * nb / n;
      a[4] += o[4] + delta[0] * delta[0] * w, a[5] += o[5] + delta[1] * delta[1] * w;
      a[6] += o[6] + delta[2] * delta[2] * w, a[7] += o[7] + delta[3] * delta[3] * w;
      a[8] += o[8] + delta[0] * delta[1] * w, a[9] += o[9] + delta[0] * delta[2] * w;
      a[10] += o[10] + delta[1] * delta[2] * w;
      for (int q = 0; q < 4; ++q) a[q] += delta[q] * nb / n;
    }
    counts_[b] += other.counts_[b];
  }
}

std::int64_t PhaseAccumulator::counts_total() const {
  return std::accumulate(counts_.begin(), counts_.end(), std::int64_t(0));
}

NodeMoments PhaseAccumulator::moments(int bin, int i) const {
  NodeMoments m;
  const double* p = data_.data() + offset(bin, i);
  std::copy(p, p + 4, m.mean.begin());
  std::copy(p + 4, p + 11, m.m2.begin());
  return m;
}

double PhaseAccumulator::rms(int bin, int i, int q) const {
  if (counts_[bin] == 0) return NAN;
  return std::sqrt(std::max(0.0, data_[offset(bin, i) + 4 + q] / double(counts_[bin])));
}

double PhaseAccumulator::reynolds_stress(int bin, int i, int a, int b) const {
  if (counts_[bin] == 0) return NAN;
  return data_[offset(bin, i) + 4 + m2_index(a, b)] / double(counts_[bin]);
}

double PhaseAccumulator::kinetic_energy(int bin, int i) const {
  if (counts_[bin] == 0) return NAN;
  const double* m2 = data_.data() + offset(bin, i) + 4;
  return 0.5 * options_.density * (m2[0] + m2[1] + m2[2]) / double(counts_[bin]);
}

std::vector<io::CheckpointArray> PhaseAccumulator::moment_arrays(std::span<const std::int64_t> rows,
                                                                 std::int64_t global_rows,
                                                                 bool root) const {
  const int cols = options_.bins * per_node;
  io::CheckpointArray moments{options_.name + "_moments",
                              global_rows,
                              cols,
                              std::vector<std::int64_t>(rows.begin(), rows.end()),
                              {}};
  moments.data.resize(rows.size() * cols);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int b = 0; b < options_.bins; ++b)
      std::copy_n(data_.data() + offset(b, int(i)), per_node,
                  moments.data.data() + i * cols + std::size_t(b) * per_node);
  io::CheckpointArray counts{options_.name + "_counts", options_.bins, 0, {}, {}};
  io::CheckpointArray meta{options_.name + "_meta", 6, 0, {}, {}};
  if (root) {
    for (int b = 0; b < options_.bins; ++b) {
      counts.rows.push_back(b);
      counts.data.push_back(double(counts_[b]));
    }
    meta.rows = {0, 1, 2, 3, 4, 5};
    meta.data = {options_.period,      double(options_.bins), options_.start_time,
                 double(first_cycle_), double(last_cycle_),   double(global_rows)};
  }
  // Moved, not copied: an initializer list would copy the moments (gigabytes on a whole mesh).
  std::vector<io::CheckpointArray> arrays;
  for (auto* a : {&moments, &counts, &meta}) arrays.push_back(std::move(*a));
  return arrays;
}

void PhaseAccumulator::restore_moments(const io::CheckpointReader& reader,
                                       std::span<const std::int64_t> rows, std::int64_t global_rows,
                                       const std::string& where) {
  const std::vector<std::int64_t> meta_rows = {0, 1, 2, 3, 4, 5};
  const auto meta = reader.read_array(options_.name + "_meta", meta_rows);
  if (meta[0] != options_.period || meta[1] != options_.bins || meta[2] != options_.start_time ||
      meta[5] != double(global_rows))
    throw std::runtime_error(fmt::format(
        "{}: saved with period {} s, {} bins, start {} s, {} points; this run has {} s, {}, {} "
        "s, {}",
        where, meta[0], meta[1], meta[2], meta[5], options_.period, options_.bins,
        options_.start_time, global_rows));
  std::vector<std::int64_t> bin_rows(options_.bins);
  std::iota(bin_rows.begin(), bin_rows.end(), 0);
  const auto counts = reader.read_array(options_.name + "_counts", bin_rows);
  for (int b = 0; b < options_.bins; ++b) counts_[b] = std::int64_t(counts[b]);
  first_cycle_ = std::int64_t(meta[3]), last_cycle_ = std::int64_t(meta[4]);
  const auto moments = reader.read_array(options_.name + "_moments", rows);
  const int cols = options_.bins * per_node;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int b = 0; b < options_.bins; ++b)
      std::copy_n(moments.data() + i * cols + std::size_t(b) * per_node, per_node,
                  data_.data() + offset(b, int(i)));
}

}  // namespace valsalva::analysis
