#include "validation/valve_closure/corner_fold.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace valsalva::validation {

namespace {

using State = std::array<double, 6>;  // x, y, th, Nx, Ny, m

State rate(const State& y, const CornerFoldInput& in) {
  const double c = std::cos(y[2]), s = std::sin(y[2]);
  return {
      c, s, y[5] / in.bending_stiffness, -in.pressure * s, in.pressure * c, s * y[3] - c * y[4]};
}

// The strip from its symmetry point over arc length `span`; every step's state if `path`.
State integrate(const CornerFoldInput& in, double n0, double m0, double span, int steps,
                std::vector<State>* path = nullptr) {
  State y{0, 0, 0, n0, 0, m0};
  const double h = span / steps;
  if (path) path->assign(1, y);
  auto add = [](const State& a, const State& k, double f) {
    State r;
    for (int i = 0; i < 6; ++i) r[i] = a[i] + f * k[i];
    return r;
  };
  for (int i = 0; i < steps; ++i) {
    const State k1 = rate(y, in), k2 = rate(add(y, k1, h / 2), in),
                k3 = rate(add(y, k2, h / 2), in), k4 = rate(add(y, k3, h), in);
    for (int c = 0; c < 6; ++c) y[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    if (path) path->push_back(y);
  }
  return y;
}

}  // namespace

CornerFold corner_fold(const CornerFoldInput& in, int steps) {
  if (!(in.bending_stiffness > 0) || !(in.thickness > 0) || !(in.pressure > 0) ||
      !(in.wedge > 0 && in.wedge < M_PI) || !(in.tension >= 0) || steps < 10)
    throw std::invalid_argument("corner_fold: D, t, p > 0, wedge in (0, pi), T >= 0 required");
  const double turn = (M_PI - in.wedge) / 2, D = in.bending_stiffness, p = in.pressure;
  // Start from the small-slope beam: end slope p (2a)^3 / (24 D) = turn, moment p (2a)^2 / 8.
  const double a0 = std::cbrt(3 * D * turn / p);
  // Unknowns scaled to order one: axial force / (p a0), moment / (p a0^2), half-span / a0.
  Eigen::Vector3d u(in.tension / (p * a0), 0.5, 1.0);
  auto residual = [&](const Eigen::Vector3d& v) {
    const State e = integrate(in, v[0] * p * a0, v[1] * p * a0 * a0, v[2] * a0, steps);
    const double tangential = e[3] * std::cos(e[2]) + e[4] * std::sin(e[2]);
    return Eigen::Vector3d(e[2] - turn, e[5] / (p * a0 * a0), (tangential - in.tension) / (p * a0));
  };
  Eigen::Vector3d r = residual(u);
  for (int it = 0; it < 50 && r.norm() > 1e-12; ++it) {
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d v = u;
      v[k] += 1e-7;
      J.col(k) = (residual(v) - r) / 1e-7;
    }
    u -= J.fullPivLu().solve(r);
    r = residual(u);
  }
  if (!(r.norm() <= 1e-10) || !(u[2] > 0))
    throw std::runtime_error(
        fmt::format("corner_fold: Newton's method did not converge (residual {:.3g})", r.norm()));

  std::vector<State> path;
  const double span = u[2] * a0;
  integrate(in, u[0] * p * a0, u[1] * p * a0 * a0, span, steps, &path);
  const State& e = path.back();
  CornerFold f;
  f.half_span = span;
  f.support_reaction = -e[3] * std::sin(e[2]) + e[4] * std::cos(e[2]);
  if (f.support_reaction < 0)
    throw std::runtime_error(
        fmt::format("corner_fold: negative support reaction {:.3g} N/m", f.support_reaction));
  // Outer face: the mid-surface moved t/2 against its normal (-sin th, cos th), towards the
  // corner. The corner lies on the symmetry axis x = 0, where the plane through the outer face's
  // point of contact, at angle `turn` to the x axis, crosses it.
  const double t = in.thickness, slope = std::tan(turn);
  auto face = [&](const State& y) {
    return Eigen::Vector2d(y[0] + t / 2 * std::sin(y[2]), y[1] - t / 2 * std::cos(y[2]));
  };
  const Eigen::Vector2d contact = face(e);
  const double corner = contact.y() - slope * contact.x();
  f.corner_to_mid = path.front()[1] - corner;
  f.corner_to_face = face(path.front()).y() - corner;
  double area = 0;  // between the face and the plane, both halves (trapezoidal rule)
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = face(path[i - 1]), b = face(path[i]);
    const double ga = a.y() - corner - slope * a.x(), gb = b.y() - corner - slope * b.x();
    area += (b.x() - a.x()) * (ga + gb) / 2;
  }
  f.uncovered_area = 2 * area;
  for (auto it = path.rbegin(); it != path.rend(); ++it)
    f.mid_surface.emplace_back(-(*it)[0], (*it)[1] - corner);
  for (std::size_t i = 1; i < path.size(); ++i)
    f.mid_surface.emplace_back(path[i][0], path[i][1] - corner);
  return f;
}

}  // namespace valsalva::validation
