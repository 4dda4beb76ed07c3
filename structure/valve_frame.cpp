#include "structure/valve_frame.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace valsalva::structure {

ValveBasis valve_basis(const ValveFrame& v) {
  const double n = v.axis.norm();
  if (!(n > 0) || !std::isfinite(n))
    throw std::invalid_argument(
        fmt::format("valve axis direction ({}, {}, {}) must be a finite non-zero vector",
                    v.axis.x(), v.axis.y(), v.axis.z()));
  if (!v.point.allFinite())
    throw std::invalid_argument(fmt::format("valve axis point ({}, {}, {}) is not finite",
                                            v.point.x(), v.point.y(), v.point.z()));
  if (!(v.annulus_radius > 0) || !std::isfinite(v.annulus_radius))
    throw std::invalid_argument(
        fmt::format("valve annulus radius R = {} m must be positive", v.annulus_radius));
  ValveBasis b;
  b.origin = v.point;
  b.axis = v.axis / n;
  // e1: the coordinate axis least aligned with the valve axis, made orthogonal to it.
  int k = 0;
  b.axis.cwiseAbs().minCoeff(&k);
  b.e1 = Vec3::Unit(k) - b.axis[k] * b.axis;
  b.e1.normalize();
  b.e2 = b.axis.cross(b.e1);
  return b;
}

}  // namespace valsalva::structure
