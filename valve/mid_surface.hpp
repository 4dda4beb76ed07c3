// The mid-surface of a one-element-thick leaflet as triangles: each element is cut half-way
// between its face in a given surface set (the aortic face) and the opposite face, sampled at
// (n+1)^2 points of that reference plane with the element's shape functions at the current
// positions, and split into 2 n^2 triangles. Used for the leaflet-crossing test and the
// coaptation measure, where the leaflets' faces (which touch and, with a penalty, overlap by a
// small penetration) would not tell crossing from contact.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "structure/solid_mesh.hpp"

namespace valsalva::valve {

using structure::Vec3;

struct TriangleSurface {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> point_axial;  // filled by the caller when needed
};

// Throws std::invalid_argument for an unknown surface set or positions that do not match.
TriangleSurface mid_surface(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                            const std::string& face_set, int n = 2);

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 2005, 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Whether segment p-q crosses triangle (a, b, c) (Moller & Trumbore, J. Graphics Tools 2, 1997),
// end points and edges included up to a relative tolerance; coplanar overlaps are not reported.
bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c);

// Whether two triangles intersect: some edge of one crosses the other.
bool triangles_intersect(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t);

}  // namespace valsalva::valve
