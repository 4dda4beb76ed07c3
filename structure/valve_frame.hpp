// The valve a leaflet index refers to: a point on the valve axis, the axis direction and the
// annulus radius R. Indices project onto the annulus plane (normal to the axis through `point`)
// with the orthonormal basis (e1, e2, axis) built here.
#pragma once

#include "structure/tensor.hpp"

namespace valsalva::structure {

struct ValveFrame {
  Vec3 point = Vec3::Zero();  // on the valve axis [m]
  Vec3 axis = Vec3::UnitZ();  // axis direction, any non-zero length
  double annulus_radius = 0;  // R [m]
};

// Unit axis and two unit vectors spanning the annulus plane, right-handed (e1 x e2 = axis).
struct ValveBasis {
  Vec3 origin, axis, e1, e2;
  Vec3 to_local(const Vec3& x) const {  // (in-plane e1, in-plane e2, along the axis)
    const Vec3 d = x - origin;
    return {d.dot(e1), d.dot(e2), d.dot(axis)};
  }
};

// Throws std::invalid_argument naming the value for a zero or non-finite axis, a non-finite
// point, or R <= 0 (or not finite).
ValveBasis valve_basis(const ValveFrame& valve);

}  // namespace valsalva::structure
