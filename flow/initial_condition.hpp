// Initial states of a flow run. The 2D Taylor-Green vortex (Taylor & Green, Proc. R. Soc. A 158,
// 1937) is also an exact solution of the Navier-Stokes equations on a periodic box of side
// 2 pi L, used to measure the error of a run:
//   u =  U0 sin(x/L) cos(y/L) F,   v = -U0 cos(x/L) sin(y/L) F,   w = 0,
//   p = rho U0^2 / 4 (cos(2x/L) + cos(2y/L)) F^2,   F = exp(-2 nu t / L^2),
// with x, y measured from the coordinate origin and Re = U0 L / nu.
// The 3D Taylor-Green vortex (the same paper; case C3.5 of the International Workshop on
// High-Order CFD Methods at Re = 1600) on a box periodic in x, y and z, at t = 0 only (it has
// no closed-form solution after that; the pressure is the exact one of the initial velocity):
//   u = U0 sin(x/L) cos(y/L) cos(z/L),  v = -U0 cos(x/L) sin(y/L) cos(z/L),  w = 0,
//   p = rho U0^2 / 16 (cos(2x/L) + cos(2y/L)) (cos(2z/L) + 2).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace valsalva::flow {

// The start of the scene key initial.type.
enum class InitialType {
  rest,
  taylor_green,
  taylor_green_3d,
  cyclic_sines,
  womersley,
  plane_poiseuille
};

// The scene names, in the order of the enum: "rest", "taylor_green", "taylor_green_3d",
// "cyclic_sines", "womersley", "plane_poiseuille".
const std::vector<std::string>& initial_type_names();
std::string to_string(InitialType type);
// std::invalid_argument naming the value and the accepted names for an unknown name.
InitialType parse_initial_type(std::string_view name);

struct InitialCondition {
  InitialType type = InitialType::rest;
  double velocity = 1.0;  // U0, m/s (taylor_green, taylor_green_3d, cyclic_sines)
  double length = 1.0;    // L, m: the period is 2 pi L (the vortices, cyclic_sines)
  // womersley: Womersley's pipe flow (flow/womersley.hpp) at t = 0 for the flow rate
  // Q(t) = flow_rate + amplitude sin(2 pi t / period + phase) in a pipe of `radius` about the
  // axis through `point` along `axis`; the velocity u(r, 0) axis (r capped at the radius), and
  // with pressure_gradient the pressure -rho G(0) (x - point) . axis of the exact solution
  // (zero on the plane through point; else p = 0, a periodic pipe driven by a body force).
  double radius = 1, flow_rate = 0, amplitude = 0, period = 1, phase = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
  bool pressure_gradient = false;
  // plane_poiseuille: the developed channel profile u = 6 U s (1 - s) along `axis` (the flow
  // direction, normalised), s = (x - point) . across / width (0 outside [0, 1]), U = `velocity`
  // the mean over the width: a channel between walls at s = 0 and 1 (`point` on the first).
  Eigen::Vector3d across = Eigen::Vector3d::UnitY();
  double width = 1;
};

// The plane-Poiseuille start of InitialCondition (type plane_poiseuille) at x.
inline Eigen::Vector3d plane_poiseuille(const Eigen::Vector3d& x, const InitialCondition& ic) {
  const double s = (x - ic.point).dot(ic.across.normalized()) / ic.width;
  if (!(s > 0 && s < 1)) return Eigen::Vector3d::Zero();
  return 6 * ic.velocity * s * (1 - s) * ic.axis.normalized();
}

// A divergence-free 3D field (each component varies only across itself), pressure 0: a start
// with motion in every direction for forced periodic boxes (the stability case):
//   u = U0 (sin(z/L), sin(x/L), sin(y/L)).
inline Eigen::Vector3d cyclic_sines(const Eigen::Vector3d& x, double u0, double length) {
  return u0 * Eigen::Vector3d(std::sin(x.z() / length), std::sin(x.x() / length),
                              std::sin(x.y() / length));
}

struct TaylorGreen {
  double u0, length, nu, rho;
  double decay(double t) const { return std::exp(-2 * nu * t / (length * length)); }
  Eigen::Vector3d velocity(const Eigen::Vector3d& x, double t) const {
    const double a = x.x() / length, b = x.y() / length, f = u0 * decay(t);
    return {std::sin(a) * std::cos(b) * f, -std::cos(a) * std::sin(b) * f, 0.0};
  }
  double pressure(const Eigen::Vector3d& x, double t) const {
    const double f = decay(t);
    return rho * u0 * u0 / 4 * (std::cos(2 * x.x() / length) + std::cos(2 * x.y() / length)) * f *
           f;
  }
};

struct TaylorGreen3d {
  double u0, length, rho;
  Eigen::Vector3d velocity(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d a = x / length;
    const double cz = std::cos(a.z());
    return {u0 * std::sin(a.x()) * std::cos(a.y()) * cz,
            -u0 * std::cos(a.x()) * std::sin(a.y()) * cz, 0.0};
  }
  double pressure(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d a = 2 * x / length;
    return rho * u0 * u0 / 16 * (std::cos(a.x()) + std::cos(a.y())) * (std::cos(a.z()) + 2);
  }
};

}  // namespace valsalva::flow
