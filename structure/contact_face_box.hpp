// A bounding box of one Lagrange contact face that provably holds the face (internal to
// contact.cpp and its tests). The contact search uses its distance to a slave point as a lower
// bound on the point's distance to the face: a face farther than the gaps the contact accepts
// needs no closest-point projection (a Newton solve), and skipping it changes no result.
//
// Why it is rigorous: a Q2 (or Q1) tensor-product Lagrange face is also a tensor-product
// Bernstein (Bezier) surface, which lies in the convex hull of its Bernstein control points
// (Farin, Curves and Surfaces for CAGD, 5th ed. 2002, ch. 5 and 16). For the 1D quadratic through
// f(-1), f(0), f(1) the control points are f(-1), 2 f(0) - (f(-1) + f(1)) / 2, f(1). The box is
// oriented along the face's tangents at its centre, so it is thin across a nearly flat face.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "structure/contact_kernel.hpp"

namespace valsalva::structure::contact_detail {

struct FaceBox {
  V3<double> centre{};
  std::array<V3<double>, 3> axes{};  // orthonormal
  V3<double> lo{}, hi{};             // extent of the control points along each axis
  double radius = 0;                 // largest distance from the centre to a control point

  // A lower bound on the distance from x to every point of the face.
  double distance(const V3<double>& x) const {
    const V3<double> d = minus(x, centre);
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      const double p = dot(axes[i], d);
      const double out = p < lo[i] ? lo[i] - p : (p > hi[i] ? p - hi[i] : 0.0);
      sum += out * out;
    }
    return std::sqrt(sum);
  }
};

// The control points of the face with node positions P (3 x 3 for Q2, 2 x 2 for Q1, indexed by
// the nodes' 1D coordinates).
template <int NF>
std::array<V3<double>, NF> bernstein_control_points(const FaceShape<NF>& f,
                                                    const std::array<V3<double>, NF>& P) {
  constexpr int n = NF == 9 ? 3 : 2;
  static_assert(NF == 9 || NF == 4, "contact faces are Q1 or Q2");
  std::array<std::array<V3<double>, n>, n> g{};
  for (int a = 0; a < NF; ++a) {
    const int i = n == 3 ? f.cs[a] + 1 : (f.cs[a] + 1) / 2;
    const int j = n == 3 ? f.ct[a] + 1 : (f.ct[a] + 1) / 2;
    g[i][j] = P[a];
  }
  if constexpr (n == 3) {
    auto middle = [](const V3<double>& a, const V3<double>& m, const V3<double>& b) {
      return V3<double>{2 * m[0] - 0.5 * (a[0] + b[0]), 2 * m[1] - 0.5 * (a[1] + b[1]),
                        2 * m[2] - 0.5 * (a[2] + b[2])};
    };
    for (int j = 0; j < 3; ++j) g[1][j] = middle(g[0][j], g[1][j], g[2][j]);
    for (int i = 0; i < 3; ++i) g[i][1] = middle(g[i][0], g[i][1], g[i][2]);
  }
  std::array<V3<double>, NF> q{};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) q[i * n + j] = g[i][j];
  return q;
}

template <int NF>
FaceBox face_box(const FaceShape<NF>& f, const std::array<V3<double>, NF>& P) {
  FaceBox box;
  V3<double> xs, xt;
  f.eval(P, 0.0, 0.0, box.centre, xs, xt);
  auto unit = [](const V3<double>& v) {
    const double l = std::sqrt(dot(v, v));
    return l > 0 ? V3<double>{v[0] / l, v[1] / l, v[2] / l} : V3<double>{0, 0, 0};
  };
  V3<double> e1 = unit(xs);
  const double c = dot(xt, e1);
  V3<double> e2 = unit(V3<double>{xt[0] - c * e1[0], xt[1] - c * e1[1], xt[2] - c * e1[2]});
  if (dot(e1, e1) == 0 || dot(e2, e2) == 0) e1 = {1, 0, 0}, e2 = {0, 1, 0};  // degenerate face
  box.axes = {e1, e2, cross(e1, e2)};
  box.lo = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  box.hi = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const V3<double>& q : bernstein_control_points<NF>(f, P)) {
    const V3<double> d = minus(q, box.centre);
    box.radius = std::max(box.radius, std::sqrt(dot(d, d)));
    for (int i = 0; i < 3; ++i) {
      const double p = dot(box.axes[i], d);
      box.lo[i] = std::min(box.lo[i], p);
      box.hi[i] = std::max(box.hi[i], p);
    }
  }
  return box;
}

}  // namespace valsalva::structure::contact_detail
