#include "validation/strip_bending/elastica.hpp"

#include <cmath>
#include <stdexcept>

namespace valsalva::validation {

namespace {
// State (theta, theta', y, x) integrated over s in [0,1] from theta'(0) = c.
struct State {
  double th, dth, y, x;
};
State shoot(double alpha, double c, int n) {
  auto rhs = [alpha](const State& s) {
    return State{s.dth, -alpha * std::cos(s.th), std::sin(s.th), std::cos(s.th)};
  };
  auto axpy = [](const State& a, double h, const State& b) {
    return State{a.th + h * b.th, a.dth + h * b.dth, a.y + h * b.y, a.x + h * b.x};
  };
  State s{0, c, 0, 0};
  const double h = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    const State k1 = rhs(s), k2 = rhs(axpy(s, h / 2, k1)), k3 = rhs(axpy(s, h / 2, k2)),
                k4 = rhs(axpy(s, h, k3));
    s.th += h / 6 * (k1.th + 2 * k2.th + 2 * k3.th + k4.th);
    s.dth += h / 6 * (k1.dth + 2 * k2.dth + 2 * k3.dth + k4.dth);
    s.y += h / 6 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y);
    s.x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
  }
  return s;
}
}  // namespace

ElasticaTip elastica_tip(double alpha, int steps) {
  if (!(alpha > 0 && alpha < 20))
    throw std::invalid_argument("elastica_tip: alpha must be in (0, 20)");
  // theta'(0) = alpha * x_tip lies in (0, alpha]; theta'(1) changes sign on that interval.
  double lo = 0, hi = alpha;
  if (shoot(alpha, hi, steps).dth < 0) throw std::runtime_error("elastica_tip: no bracket");
  for (int it = 0; it < 200 && hi - lo > 1e-15 * alpha; ++it) {
    const double mid = 0.5 * (lo + hi);
    (shoot(alpha, mid, steps).dth < 0 ? lo : hi) = mid;
  }
  const State s = shoot(alpha, 0.5 * (lo + hi), steps);
  return {s.y, 1 - s.x, s.th};
}

}  // namespace valsalva::validation
