// Pulsatile generalised-Newtonian pipe flow in 1D; see radial_pulsatile.hpp.
#include "validation/womersley_rheology/radial_pulsatile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace valsalva::validation {

namespace {

// Face conductances a_f = r_f nu(|du/dr|_f) / dr of the velocity `u` (u_N = 0 appended).
void conductances(const PulsatilePipe& pipe, const std::vector<double>& u, double dr,
                  std::vector<double>& a) {
  const std::size_t n = u.size();  // unknowns 0 .. N-1, the wall node N is 0
  for (std::size_t i = 0; i < n; ++i) {
    const double next = i + 1 < n ? u[i + 1] : 0.0;
    const double gamma = std::abs(next - u[i]) / dr;
    const double rf = (static_cast<double>(i) + 0.5) * dr;
    a[i] = rf * flow::apparent_viscosity(pipe.model, gamma) / pipe.density / dr;
  }
}

double flow_rate(const std::vector<double>& u, double dr) {
  double q = 0;  // trapezoidal rule on u r, u_N = 0
  for (std::size_t i = 1; i < u.size(); ++i) q += u[i] * static_cast<double>(i) * dr;
  return 2 * std::numbers::pi * q * dr;
}

double wall_shear(const PulsatilePipe& pipe, const std::vector<double>& u, double dr) {
  const std::size_t n = u.size();
  const double dudr = (-4 * u[n - 1] + u[n - 2]) / (2 * dr);
  return -flow::apparent_viscosity(pipe.model, std::abs(dudr)) * dudr;
}

}  // namespace

PulsatileHistory pulsatile_pipe(const PulsatilePipe& pipe, int periods, int cells, int steps) {
  if (periods < 1 || cells < 4 || steps < 2 || !(pipe.radius > 0) || !(pipe.period > 0) ||
      !(pipe.density > 0) || !pipe.gradient)
    throw std::invalid_argument(fmt::format(
        "pulsatile_pipe: {} periods, {} cells, {} steps, radius {:g}, period {:g}, density {:g}",
        periods, cells, steps, pipe.radius, pipe.period, pipe.density));
  const auto n = static_cast<std::size_t>(cells);
  const double dr = pipe.radius / cells, dt = pipe.period / steps;
  std::vector<double> volume(n), u(n, 0.0), old(n, 0.0), guess(n), a(n), rhs(n);
  std::vector<double> lower(n), diag(n), upper(n);
  volume[0] = dr * dr / 8;
  for (std::size_t i = 1; i < n; ++i) volume[i] = static_cast<double>(i) * dr * dr;
  PulsatileHistory h;
  h.start.radius = pipe.radius;
  std::vector<double> previous_start(n, 0.0);
  double peak = 0;
  const long total = static_cast<long>(periods) * steps;
  const long last = total - steps;
  for (long k = 0; k <= total; ++k) {
    const double t = static_cast<double>(k) * dt;
    if (k >= last) {
      if (k == last) {
        h.start.u.assign(u.begin(), u.end());
        h.start.u.push_back(0.0);
        h.start.flow_rate = flow_rate(u, dr);
      }
      h.time.push_back(t);
      h.flow_rate.push_back(flow_rate(u, dr));
      h.wall_shear.push_back(wall_shear(pipe, u, dr));
      for (double x : u) peak = std::max(peak, std::abs(x));
    }
    if (k == last - steps) previous_start = u;
    if (k == total) break;
    // BDF2 (backward Euler on the first step), L-stable: the stiff viscous modes of a start
    // from rest are damped, not carried on as Crank-Nicolson would.
    const bool first = k == 0;
    for (std::size_t i = 0; i < n; ++i) guess[i] = first ? u[i] : 2 * u[i] - old[i];
    conductances(pipe, guess, dr, a);
    const double c0 = first ? 1.0 : 1.5, g = pipe.gradient(t + dt);
    for (std::size_t i = 0; i < n; ++i) {
      const double left = i > 0 ? a[i - 1] : 0.0;
      lower[i] = -dt * left / volume[i];
      upper[i] = -dt * a[i] / volume[i];
      diag[i] = c0 + dt * (left + a[i]) / volume[i];
      rhs[i] = (first ? u[i] : 2 * u[i] - 0.5 * old[i]) + dt * g;
    }
    for (std::size_t i = 1; i < n; ++i) {  // Thomas algorithm
      const double m = lower[i] / diag[i - 1];
      diag[i] -= m * upper[i - 1];
      rhs[i] -= m * rhs[i - 1];
    }
    old = u;
    u[n - 1] = rhs[n - 1] / diag[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) u[i] = (rhs[i] - upper[i] * u[i + 1]) / diag[i];
  }
  for (std::size_t i = 0; i < n; ++i)
    h.cycle_change = std::max(h.cycle_change, std::abs(h.start.u[i] - previous_start[i]));
  h.cycle_change /= std::max(peak, 1e-300);
  return h;
}

CycleSummary cycle_summary(const std::vector<double>& time, const std::vector<double>& value,
                           double t0, double period) {
  constexpr int points = 4096;
  if (time.size() != value.size() || time.size() < 2 || time.front() > t0 + 1e-9 * period ||
      time.back() < t0 + period * (1 - 1e-9))
    throw std::invalid_argument(fmt::format(
        "cycle_summary: {} samples from {:g} to {:g} s do not cover [{:g}, {:g}] s", time.size(),
        time.empty() ? 0.0 : time.front(), time.empty() ? 0.0 : time.back(), t0, t0 + period));
  CycleSummary s;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -s.min;
  double sin_sum = 0, cos_sum = 0;
  std::size_t j = 0;
  for (int k = 0; k < points; ++k) {
    const double t = t0 + period * k / points;
    while (j + 2 < time.size() && time[j + 1] < t) ++j;
    const double w = std::clamp((t - time[j]) / (time[j + 1] - time[j]), 0.0, 1.0);
    const double f = (1 - w) * value[j] + w * value[j + 1];
    const double arg = 2 * std::numbers::pi * k / points;
    s.mean += f / points;
    s.mean_abs += std::abs(f) / points;
    sin_sum += 2 * f * std::sin(arg) / points;
    cos_sum += 2 * f * std::cos(arg) / points;
    s.min = std::min(s.min, f);
    s.max = std::max(s.max, f);
  }
  s.amplitude = std::hypot(sin_sum, cos_sum);
  s.phase = std::atan2(cos_sum, sin_sum);
  s.osi = s.mean_abs > 0 ? 0.5 * (1 - std::abs(s.mean) / s.mean_abs) : 0.0;
  return s;
}

}  // namespace valsalva::validation
