// Gauss-point-to-surface contact kernel (internal to contact.cpp and its tests): the geometry of
// one hexahedron face as a Lagrange surface in its face parameters (s, t), the closest-point
// projection of a point onto it, and the penalty force of one slave Gauss point. Templated on the
// scalar so that the same code gives the force (double) and, with forward-mode automatic
// differentiation (Eigen's AutoDiffScalar), its exact derivative for the Newton tangent. The
// projection parameters' derivative comes from one Newton step of the projection equations taken
// in the AD scalar from the converged (double) parameters: the Newton map has zero derivative at
// its fixed point, so that step carries exactly the implicit-function derivative
// d(s,t)/dx = -J^-1 dR/dx (Wriggers, Computational Contact Mechanics, 2nd ed. 2006, ch. 4).
#pragma once

#include <array>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "structure/hex_element.hpp"

namespace valsalva::structure::contact_detail {

template <class T>
using V3 = std::array<T, 3>;

template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
V3<T> minus(const V3<T>& a, const V3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double value_of(double v) {
  return v;
}
template <class D>
double value_of(const Eigen::AutoDiffScalar<D>& v) {
  return v.value();
}

// 1D Lagrange basis function of the node at coordinate c (in {-1, 1} for Q1, {-1, 0, 1} for Q2):
// value, first and second derivative at xi.
template <class T>
T lagrange(int order, int c, const T& xi) {
  if (order == 1) return c < 0 ? T(0.5 * (1.0 - xi)) : T(0.5 * (1.0 + xi));
  if (c < 0) return T(0.5 * xi * (xi - 1.0));
  if (c > 0) return T(0.5 * xi * (xi + 1.0));
  return T(1.0 - xi * xi);
}
template <class T>
T lagrange_d(int order, int c, const T& xi) {
  if (order == 1) return T(c < 0 ? -0.5 : 0.5);
  if (c < 0) return T(xi - 0.5);
  if (c > 0) return T(xi + 0.5);
  return T(-2.0 * xi);
}
inline double lagrange_dd(int order, int c) {
  if (order == 1) return 0;
  return c == 0 ? -2.0 : 1.0;
}

// Face `face` of a hexahedron of order `order` with NF nodes (4 or 9): (s, t) are the reference
// coordinates (axis + 1) % 3 and (axis + 2) % 3; side (x_s x x_t) points out of the element.
template <int NF>
struct FaceShape {
  int order = 2, side = 1;
  std::array<int, NF> local{};     // local element node of each face node
  std::array<int, NF> cs{}, ct{};  // its 1D node coordinates along s and t

  FaceShape() = default;
  FaceShape(HexOrder o, int face) : order(static_cast<int>(o)) {
    const HexFace f = hex_face(face);
    side = f.side;
    const auto nodes = hex_face_nodes(o, face);
    for (int a = 0; a < NF; ++a) {
      local[a] = nodes[a];
      const Vec3 r = hex_reference_node(o, nodes[a]);
      cs[a] = static_cast<int>(std::lround(r[(f.axis + 1) % 3]));
      ct[a] = static_cast<int>(std::lround(r[(f.axis + 2) % 3]));
    }
  }

  // Position and tangents at (s, t) for node positions P[a].
  template <class T, class S>
  void eval(const std::array<V3<T>, NF>& P, const S& s, const S& t, V3<T>& x, V3<T>& xs,
            V3<T>& xt) const {
    x = xs = xt = {T(0), T(0), T(0)};
    for (int a = 0; a < NF; ++a) {
      const S ls = lagrange(order, cs[a], s), lt = lagrange(order, ct[a], t);
      const S n = ls * lt, ns = lagrange_d(order, cs[a], s) * lt,
              nt = ls * lagrange_d(order, ct[a], t);
      for (int i = 0; i < 3; ++i) {
        x[i] += n * P[a][i];
        xs[i] += ns * P[a][i];
        xt[i] += nt * P[a][i];
      }
    }
  }
  // Position, first and second derivatives at (s, t) in one pass (double only: the projection's
  // Newton iteration). The 1D bases are evaluated once per coordinate, not once per node.
  void eval_newton(const std::array<V3<double>, NF>& P, double s, double t, V3<double>& x,
                   V3<double>& xs, V3<double>& xt, V3<double>& xss, V3<double>& xst,
                   V3<double>& xtt) const {
    std::array<double, 3> ls, ds, dds, lt, dt, ddt;  // indexed by the node coordinate + 1
    for (int c = -1; c <= 1; ++c) {
      ls[c + 1] = lagrange(order, c, s), ds[c + 1] = lagrange_d(order, c, s);
      lt[c + 1] = lagrange(order, c, t), dt[c + 1] = lagrange_d(order, c, t);
      dds[c + 1] = ddt[c + 1] = lagrange_dd(order, c);
    }
    x = xs = xt = xss = xst = xtt = {0, 0, 0};
    for (int a = 0; a < NF; ++a) {
      const int i_s = cs[a] + 1, i_t = ct[a] + 1;
      const double n = ls[i_s] * lt[i_t], ns = ds[i_s] * lt[i_t], nt = ls[i_s] * dt[i_t],
                   nss = dds[i_s] * lt[i_t], nst = ds[i_s] * dt[i_t], ntt = ls[i_s] * ddt[i_t];
      for (int i = 0; i < 3; ++i) {
        x[i] += n * P[a][i];
        xs[i] += ns * P[a][i];
        xt[i] += nt * P[a][i];
        xss[i] += nss * P[a][i];
        xst[i] += nst * P[a][i];
        xtt[i] += ntt * P[a][i];
      }
    }
  }
};

// Closest-point projection of xp onto the face: (x_p - x(s,t)) . x_{s,t} = 0 by Newton's method
// from the face centre. inside: converged with |s|, |t| <= 1 + tol. gap: signed distance along
// the outward unit normal (negative: xp is behind the face, inside the body).
struct Projection {
  bool inside = false;
  double s = 0, t = 0, gap = 0;
  double Jinv[2][2] = {{0, 0}, {0, 0}};  // inverse of dR/d(s, t) at the solution
  int iterations = 0;                    // Newton iterations taken (work counter)
};

// stop_outside: give up once Newton converges outside the face (below); false: the reference
// that iterates to convergence.
template <int NF>
Projection project(const FaceShape<NF>& f, const std::array<V3<double>, NF>& P,
                   const V3<double>& xp, bool stop_outside = true) {
  Projection pr;
  double s = 0, t = 0;
  bool converged = false;
  int clamped = 0;
  for (int it = 0; it < 25; ++it) {
    pr.iterations = it + 1;
    V3<double> x, xs, xt, xss, xst, xtt;
    f.eval_newton(P, s, t, x, xs, xt, xss, xst, xtt);
    const V3<double> d = minus(xp, x);
    const double R0 = dot(d, xs), R1 = dot(d, xt);
    const double J00 = -dot(xs, xs) + dot(d, xss), J01 = -dot(xs, xt) + dot(d, xst),
                 J11 = -dot(xt, xt) + dot(d, xtt);
    const double det = J00 * J11 - J01 * J01;
    if (!(std::abs(det) > 0)) return pr;
    pr.Jinv[0][0] = J11 / det;
    pr.Jinv[0][1] = pr.Jinv[1][0] = -J01 / det;
    pr.Jinv[1][1] = J00 / det;
    const double ds = -(pr.Jinv[0][0] * R0 + pr.Jinv[0][1] * R1);
    const double dt = -(pr.Jinv[1][0] * R0 + pr.Jinv[1][1] * R1);
    s = std::clamp(s + ds, -2.0, 2.0);
    t = std::clamp(t + dt, -2.0, 2.0);
    // Held at the clamp for three iterations in a row: the closest point lies far outside the
    // face (|s| or |t| >= 2, never accepted); without this exit a quarter of the calls of a
    // closed valve ran all 25 iterations.
    clamped = std::abs(s) == 2.0 || std::abs(t) == 2.0 ? clamped + 1 : 0;
    if (clamped == 3) return pr;
    // Converging outside the face: with Newton's quadratic convergence a step below 1e-4 leaves
    // s and t within about 1e-8 of their limit, so |s| or |t| above 1 + 1e-2 is never accepted.
    if (stop_outside && std::abs(ds) + std::abs(dt) < 1e-4 &&
        std::max(std::abs(s), std::abs(t)) > 1 + 1e-2)
      return pr;
    if (std::abs(ds) + std::abs(dt) < 1e-13) {
      converged = true;
      break;
    }
  }
  constexpr double tol = 1e-9;
  if (!converged || std::abs(s) > 1 + tol || std::abs(t) > 1 + tol) return pr;
  V3<double> x, xs, xt;
  f.eval(P, s, t, x, xs, xt);
  V3<double> n = cross(xs, xt);
  const double len = std::sqrt(dot(n, n));
  if (!(len > 0)) return pr;
  pr.inside = true;
  pr.s = s;
  pr.t = t;
  pr.gap = f.side * dot(minus(xp, x), n) / len;
  return pr;
}

// Slave quadrature point data: shape function values and s/t derivatives of the slave face
// nodes at the point, and its reference weight.
template <int NF>
struct SlavePoint {
  std::array<double, NF> N{}, Ns{}, Nt{};
  double weight = 0;
};

template <class T, int NF>
struct PointForce {
  std::array<V3<T>, NF> f;   // on the slave face nodes
  std::array<V3<T>, NF> fm;  // its reaction on the master face nodes, -N_b(closest point) p n da
  T gap, pressure, area;     // area: current da of the point (weight included)
};

// Slave position, current area element and outward normal orientation.
template <class T, int NF>
void slave_geometry(const FaceShape<NF>& fs, const SlavePoint<NF>& sp,
                    const std::array<V3<T>, NF>& Ps, V3<T>& xs, T& da) {
  using std::sqrt;
  V3<T> as{T(0), T(0), T(0)}, at = as;
  xs = as;
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) {
      xs[i] += sp.N[a] * Ps[a][i];
      as[i] += sp.Ns[a] * Ps[a][i];
      at[i] += sp.Nt[a] * Ps[a][i];
    }
  const V3<T> A = cross(as, at);
  da = sqrt(dot(A, A)) * sp.weight;
  (void)fs;
}

// Penalty pressure p(g) for a gap g: eps <-g>, or with a smoothing width w > 0 the C1 form
// eps g^2 / (2 w) for -w < g < 0 and eps (-g - w / 2) below, so that the residual is
// differentiable where a point enters contact and Newton does not chatter on the active set
// (the quadratically regularised penalty of Wriggers, Computational Contact Mechanics, 2nd ed.
// 2006, sect. 10.3). It adds at most w / 2 of penetration at a given pressure.
template <class T>
T penalty_pressure(const T& g, double eps, double width) {
  if (value_of(g) >= 0) return T(0);
  if (width > 0 && value_of(g) > -width) return T((eps / (2 * width)) * (g * g));
  return T(-eps * (g + 0.5 * width));
}

// Penalty force of the two-half-pass Gauss-point-to-surface formulation (Sauer & De Lorenzis,
// CMAME 253, 2013): f_a = N_a p n_m da on the slave nodes only, with
// p = eps <-g>, g = (x_s - x_m) . n_m and n_m the master's outward unit normal at the closest
// point, da the slave's current area element. With a clearance c the pressure is p(g - c).
template <class T, int NF>
PointForce<T, NF> face_point_force(const FaceShape<NF>& fs, const SlavePoint<NF>& sp,
                                   const std::array<V3<T>, NF>& Ps, const FaceShape<NF>& fm,
                                   const std::array<V3<T>, NF>& Pm, const Projection& pr,
                                   double eps, double width, double clearance = 0) {
  using std::sqrt;
  PointForce<T, NF> out;
  V3<T> xs;
  slave_geometry<T, NF>(fs, sp, Ps, xs, out.area);
  // One Newton step of the projection in T (value unchanged, derivative = implicit derivative).
  V3<T> xm, ms, mt;
  fm.eval(Pm, pr.s, pr.t, xm, ms, mt);
  const V3<T> d = minus(xs, xm);
  const T R0 = dot(d, ms), R1 = dot(d, mt);
  const T s1 = pr.s - (pr.Jinv[0][0] * R0 + pr.Jinv[0][1] * R1);
  const T t1 = pr.t - (pr.Jinv[1][0] * R0 + pr.Jinv[1][1] * R1);
  fm.eval(Pm, s1, t1, xm, ms, mt);
  V3<T> n = cross(ms, mt);
  const T len = sqrt(dot(n, n));
  for (int i = 0; i < 3; ++i) n[i] = static_cast<double>(fm.side) * n[i] / len;
  out.gap = dot(minus(xs, xm), n);
  out.pressure = penalty_pressure(out.gap - clearance, eps, width);
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) out.f[a][i] = sp.N[a] * out.pressure * out.area * n[i];
  for (int b = 0; b < NF; ++b) {
    const T Nb = lagrange(fm.order, fm.cs[b], s1) * lagrange(fm.order, fm.ct[b], t1);
    for (int i = 0; i < 3; ++i) out.fm[b][i] = -Nb * out.pressure * out.area * n[i];
  }
  return out;
}

// Rigid analytic obstacle: a plane (point p, unit normal d pointing into the allowed side) or a
// cylinder (axis through p along unit d, radius R; the body stays inside it, or outside).
struct ObstacleShape {
  bool cylinder = false, inside = true;
  V3<double> p{0, 0, 0}, d{0, 0, 1};
  double radius = 0;
};

// Signed gap of x to the obstacle and the unit normal pointing into the allowed region.
template <class T>
T obstacle_gap(const ObstacleShape& o, const V3<T>& x, V3<T>& n) {
  using std::sqrt;
  V3<T> r{x[0] - o.p[0], x[1] - o.p[1], x[2] - o.p[2]};
  if (!o.cylinder) {
    for (int i = 0; i < 3; ++i) n[i] = T(o.d[i]);
    return r[0] * o.d[0] + r[1] * o.d[1] + r[2] * o.d[2];
  }
  const T along = r[0] * o.d[0] + r[1] * o.d[1] + r[2] * o.d[2];
  for (int i = 0; i < 3; ++i) r[i] -= along * o.d[i];
  const T rho = sqrt(dot(r, r));
  const double sign = o.inside ? -1.0 : 1.0;
  for (int i = 0; i < 3; ++i) n[i] = sign * r[i] / rho;
  return o.inside ? T(o.radius - rho) : T(rho - o.radius);
}

// Penalty force of a slave Gauss point against a rigid obstacle: f_a = N_a eps <-g> n da.
template <class T, int NF>
PointForce<T, NF> obstacle_point_force(const FaceShape<NF>& fs, const SlavePoint<NF>& sp,
                                       const std::array<V3<T>, NF>& Ps, const ObstacleShape& o,
                                       double eps, double width) {
  PointForce<T, NF> out;
  V3<T> xs, n;
  slave_geometry<T, NF>(fs, sp, Ps, xs, out.area);
  out.gap = obstacle_gap(o, xs, n);
  out.pressure = penalty_pressure(out.gap, eps, width);
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) out.f[a][i] = sp.N[a] * out.pressure * out.area * n[i];
  return out;
}

}  // namespace valsalva::structure::contact_detail
