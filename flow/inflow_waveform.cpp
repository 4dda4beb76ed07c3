// Flow-rate waveforms; see inflow_waveform.hpp.
#include "flow/inflow_waveform.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace valsalva::flow {

namespace {

double unramped(const Waveform& w, double time) {
  const auto& t = w.t;
  const auto& q = w.q;
  switch (w.kind) {
    case Waveform::Kind::constant:
      return w.mean;
    case Waveform::Kind::sine:
      return w.mean + w.amplitude * std::sin(2 * std::numbers::pi * time / w.period + w.phase);
    case Waveform::Kind::table: {
      const double span = t.back() - t.front();
      double s = std::fmod(time - t.front(), span);
      if (s < 0) s += span;
      s += t.front();
      const auto it = std::upper_bound(t.begin(), t.end(), s);
      const std::size_t k = std::clamp<std::size_t>(it - t.begin(), 1, t.size() - 1);
      const double a = (s - t[k - 1]) / (t[k] - t[k - 1]);
      return (1 - a) * q[k - 1] + a * q[k];
    }
  }
  return 0;
}

}  // namespace

double Waveform::operator()(double time) const {
  const double q = unramped(*this, time);
  if (!(ramp > 0) || time >= ramp) return q;
  if (time <= 0) return 0;
  return q * 0.5 * (1 - std::cos(std::numbers::pi * time / ramp));
}

Waveform table_waveform(std::vector<double> t, std::vector<double> q) {
  if (t.size() != q.size() || t.size() < 2)
    throw WaveformError(fmt::format("a waveform table needs at least two rows (t, Q), found {}",
                                    std::min(t.size(), q.size())));
  for (std::size_t k = 1; k < t.size(); ++k)
    if (!(t[k] > t[k - 1]))
      throw WaveformError(
          fmt::format("row {}: time {} is not after the previous row's {}", k + 1, t[k], t[k - 1]));
  Waveform w;
  w.kind = Waveform::Kind::table;
  w.t = std::move(t);
  w.q = std::move(q);
  w.period = w.t.back() - w.t.front();
  w.mean = 0;
  for (std::size_t k = 1; k < w.t.size(); ++k)
    w.mean += 0.5 * (w.q[k] + w.q[k - 1]) * (w.t[k] - w.t[k - 1]) / w.period;
  return w;
}

}  // namespace valsalva::flow
