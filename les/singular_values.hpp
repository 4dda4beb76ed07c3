// Singular values of a 3x3 velocity gradient g, sigma1 >= sigma2 >= sigma3 >= 0, from the
// eigenvalues of G = g^T g by the closed-form invariant (trigonometric) method, as prescribed for
// the Sigma model (Nicoud, Toda, Cabrit, Bose, Lee, Phys. Fluids 23, 085106, 2011, appendix).
//
// Why the details differ from the textbook formula:
// - The textbook angle acos(q / p^3) loses half the digits near a double eigenvalue (axisymmetric
//   strain, solid rotation), where the Sigma model must vanish. We take the angle from
//   atan2(sqrt(disc/108), q), with the discriminant disc = prod (l_i - l_j)^2 written as the Gram
//   determinant of {I, B, B^2} (Parlett, Linear Algebra Appl. 355 (2002) 85-101) expanded by
//   Cauchy-Binet into a sum of squares: it is then accurate to round-off and never negative.
// - p and q come from the deviator B = G - tr(G)/3 I (no cancellation in tr(B^2)).
// - sigma3 = |det g| / (sigma1 sigma2): the squared condition number of G does not reach it;
//   when sigma2 < 0.1 sigma1, sigma2 comes from a deflated 2x2 problem (detail::small_pair).
// - g is scaled by a power of two (exact) so that G cannot overflow or underflow.
// - Eigenvalues are clipped at 0 and sigma3 at sigma2 (safe clipping of round-off).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()
#include <Eigen/LU>        // determinant()
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace valsalva::les {

namespace detail {
// (lambda2, sigma2 sigma3) when lambda2 << lambda1. From G alone lambda2 carries an absolute
// error eps*lambda1, i.e. only sqrt(eps) relative accuracy in sigma2 for a nearly rank-one g
// (pure shear), and the 2x2 minors inside det(g) carry eps*sigma1^2. Deflate instead:
// v1 = the lambda1 eigenvector (cross product of two rows of G - lambda1 I, well conditioned as
// lambda1 is isolated), [a b] an orthonormal basis of its complement, H = g [a b]: lambda2 from
// the 2x2 H^T H in closed form, sigma2 sigma3 = |g a x g b|.
inline Eigen::Vector2d small_pair(const Eigen::Matrix3d& g, const Eigen::Matrix3d& G, double l1) {
  Eigen::Matrix3d M = G;
  M.diagonal().array() -= l1;
  Eigen::Vector3d v1 = M.row(0).cross(M.row(1)).transpose();
  for (const auto& c :
       {Eigen::Vector3d(M.row(0).cross(M.row(2))), Eigen::Vector3d(M.row(1).cross(M.row(2)))})
    if (c.squaredNorm() > v1.squaredNorm()) v1 = c;
  if (!(v1.squaredNorm() > 0.0)) return Eigen::Vector2d::Zero();
  v1.normalize();
  Eigen::Index axis = 0;
  v1.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d a = Eigen::Vector3d::Unit(axis).cross(v1).normalized();
  const Eigen::Vector3d b = v1.cross(a);
  const Eigen::Vector3d ha = g * a, hb = g * b;
  const double kaa = ha.squaredNorm(), kbb = hb.squaredNorm(), kab = ha.dot(hb);
  return {0.5 * (kaa + kbb) + std::hypot(0.5 * (kaa - kbb), kab), ha.cross(hb).norm()};
}
}  // namespace detail

inline Eigen::Vector3d singular_values(const Eigen::Matrix3d& g) {
  if (!g.allFinite()) return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const double gmax = g.cwiseAbs().maxCoeff();
  if (gmax == 0.0) return Eigen::Vector3d::Zero();
  const int e = std::ilogb(gmax);
  const Eigen::Matrix3d gs = g * std::ldexp(1.0, -e);  // exact scaling, entries in [1, 2)

  const Eigen::Matrix3d G = gs.transpose() * gs;
  const double m = G.trace() / 3.0;
  Eigen::Matrix3d B = G;
  B.diagonal().array() -= m;
  const Eigen::Matrix3d C = B * B;

  // p^2 = tr(B^2)/6, q = det(B)/2: eigenvalues m + 2p cos(phi + 2 pi k/3).
  const double trB2 = B(0, 0) * B(0, 0) + B(1, 1) * B(1, 1) + B(2, 2) * B(2, 2) +
                      2.0 * (B(0, 1) * B(0, 1) + B(0, 2) * B(0, 2) + B(1, 2) * B(1, 2));
  const double p = std::sqrt(trB2 / 6.0);
  const double q = 0.5 * B.determinant();

  // Discriminant as a sum of squares of the 3x3 minors of the 6x3 matrix whose rows are
  // (I, B, B^2) at the diagonal positions (weight 1) and the off-diagonal ones (weight sqrt 2).
  constexpr int od[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  double disc = 0.0;
  for (int a = 0; a < 3; ++a)  // one diagonal row + two off-diagonal rows (x3 diagonal choices)
    for (int b = a + 1; b < 3; ++b) {
      const double mnr = B(od[a][0], od[a][1]) * C(od[b][0], od[b][1]) -
                         B(od[b][0], od[b][1]) * C(od[a][0], od[a][1]);
      disc += 12.0 * mnr * mnr;
    }
  for (int i = 0; i < 3; ++i)  // two diagonal rows + one off-diagonal row
    for (int j = i + 1; j < 3; ++j)
      for (const auto& o : od) {
        const double mnr =
            (B(j, j) - B(i, i)) * C(o[0], o[1]) - (C(j, j) - C(i, i)) * B(o[0], o[1]);
        disc += 2.0 * mnr * mnr;
      }
  {  // three diagonal rows
    const double mnr =
        (B(1, 1) - B(0, 0)) * (C(2, 2) - C(0, 0)) - (B(2, 2) - B(0, 0)) * (C(1, 1) - C(0, 0));
    disc += mnr * mnr;
  }

  const double phi = std::atan2(std::sqrt(disc / 108.0), q) / 3.0;  // in [0, pi/3]
  constexpr double third = 2.0 * std::numbers::pi / 3.0;
  const double l1 = std::max(m + 2.0 * p * std::cos(phi), 0.0);
  const double l2 = std::max(m + 2.0 * p * std::cos(phi - third), 0.0);
  const double s1 = std::sqrt(l1);
  double s2 = 0.0, s23 = 0.0;  // sigma2 and sigma2 * sigma3
  if (l2 < 1e-2 * l1) {
    const Eigen::Vector2d pair = detail::small_pair(gs, G, l1);
    s2 = std::min(std::sqrt(pair(0)), s1);
    s23 = pair(1);
  } else {
    s2 = std::min(std::sqrt(l2), s1);
    s23 = std::abs(gs.determinant()) / s1;
  }
  const double s3 = s2 > 0.0 ? std::min(s23 / s2, s2) : 0.0;
  return Eigen::Vector3d(s1, s2, s3) * std::ldexp(1.0, e);
}

}  // namespace valsalva::les
