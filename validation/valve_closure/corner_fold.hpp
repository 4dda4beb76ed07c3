// Reference for the fold of a closed leaflet at the valve axis: a plate strip (bending stiffness
// D, thickness t, plane strain) pressed by a uniform pressure p into the corner between two
// frictionless planes of interior angle `wedge`, symmetric about the corner's bisector, with an
// in-plane tension T where it lies on the planes. Where each leaflet of a three-fold symmetric
// valve meets the axis it lies in such a 120-degree corner (its commissure planes). The strip
// cannot follow the corner: it leaves the planes and bridges it with the inextensible elastica
//   x' = cos th, y' = sin th, th' = m / D, N' = p (-sin th, cos th), m' = sin th Nx - cos th Ny,
// from its symmetry point (th = 0, shear 0) to the points where it leaves the planes (th = the
// half turn (pi - wedge) / 2, m = 0: a frictionless flat support carries no moment; tangential
// force = T), integrated with RK4 and the three unknowns (axial force and moment at the symmetry
// point, half-span) found by Newton's method. What is left between the strip's outer face and
// the corner is uncovered: the part of a closed valve's orifice that bending alone keeps open.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace valsalva::validation {

struct CornerFoldInput {
  double bending_stiffness;  // D = E t^3 / (12 (1 - nu^2)) [N m]
  double thickness;          // [m]
  double pressure;           // on the strip's inner face, towards the corner [Pa]
  double wedge;              // interior angle of the corner [rad], in (0, pi)
  double tension = 0;        // in-plane tension where the strip lies on the planes [N/m]
};

struct CornerFold {
  double half_span = 0;         // arc length from the symmetry point to a plane [m]
  double corner_to_mid = 0;     // corner to the mid-surface's symmetry point [m]
  double corner_to_face = 0;    // corner to the outer face [m]
  double uncovered_area = 0;    // between the outer face and the corner [m^2]
  double support_reaction = 0;  // line force at each point where the strip leaves a plane [N/m]
  // The bridging part of the mid-surface, from one plane to the other, in the corner's frame
  // (corner at the origin, bisector along +y) [m].
  std::vector<Eigen::Vector2d> mid_surface;
};

// Throws std::runtime_error when Newton's method does not converge or the reaction comes out
// negative (the strip would pull on the plane), std::invalid_argument for bad input.
CornerFold corner_fold(const CornerFoldInput& in, int steps = 2000);

}  // namespace valsalva::validation
