// Singular values of a 3x3 velocity gradient g, sigma1 >= sigma2 >= sigma3 >= 0, from the
// eigenvalues of G = g^T g by the closed-form invariant (trigonometric) method, as prescribed for
// the Sigma model (Nicoud, Toda, Cabrit, Bose, Lee, Phys. Fluids 23, 085106, 2011, appendix).
//
// Why the details differ from the textbook formula:
// - The textbook angle acos(q / p^3) loses half the digits near a double eigenvalue (axisymmetric
//   strain, solid rotation), where the Sigma model must vanish. We take the split of the double
//   pair from the discriminant disc = prod (l_i - l_j)^2 written as the Gram determinant of
//   {I, B, B^2} (Parlett, Linear Algebra Appl. 355 (2002) 85-101) expanded by Cauchy-Binet into a
//   sum of squares: it is then accurate to round-off and never negative. The isolated eigenvalue
//   comes from two Newton steps on the normalised cubic (no acos/atan2/cos: this kernel runs at
//   every node, and the trigonometric form cost a third of it).
// - p and q come from the deviator B = G - tr(G)/3 I (no cancellation in tr(B^2)).
// - sigma3 = |det g| / (sigma1 sigma2): the squared condition number of G does not reach it;
//   when sigma2 < 0.1 sigma1, sigma2 comes from a deflated 2x2 problem (detail::small_pair).
// - g is scaled by a power of two (exact) so that G cannot overflow or underflow.
// - Cost (it runs at every node): symmetric G, B, B^2 as scalars, scaling by exponent bits.
// - Eigenvalues are clipped at 0 and sigma3 at sigma2 (safe clipping of round-off).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()
#include <Eigen/LU>        // determinant()
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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

namespace detail {
// 2^k for k in [-1022, 1023], built from its bits (std::ldexp is a library call, and this sits
// in the subgrid kernel that runs at every node and RK stage).
inline double pow2(int k) {
  return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}
}  // namespace detail

inline Eigen::Vector3d singular_values(const Eigen::Matrix3d& g) {
  // A sum of magnitudes is NaN or inf when any entry is, and within 9x of the largest entry.
  const double gsum = g.cwiseAbs().sum();
  if (!(gsum <= std::numeric_limits<double>::max()))
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (gsum == 0.0) return Eigen::Vector3d::Zero();
  // Exact power-of-two scaling to entries below 2; the bit trick covers all normal exponents
  // but the two extremes, where ldexp takes over.
  const int biased = static_cast<int>(std::bit_cast<std::uint64_t>(gsum) >> 52);  // gsum > 0
  const int e = biased > 1 && biased < 2046 ? biased - 1023 : std::ilogb(gsum);
  const bool normal = e > -1022 && e < 1023;
  const double down = normal ? detail::pow2(-e) : std::ldexp(1.0, -e);
  const Eigen::Matrix3d gs = g * down;

  // G = gs^T gs and its deviator B = G - m I, symmetric: six entries each.
  const auto col = [&](int a, int b) { return gs.col(a).dot(gs.col(b)); };
  const double g00 = col(0, 0), g11 = col(1, 1), g22 = col(2, 2);
  const double b01 = col(0, 1), b02 = col(0, 2), b12 = col(1, 2);
  const double m = (g00 + g11 + g22) / 3.0;
  const double b00 = g00 - m, b11 = g11 - m, b22 = g22 - m;
  // C = B^2 (symmetric).
  const double c00 = b00 * b00 + b01 * b01 + b02 * b02;
  const double c11 = b01 * b01 + b11 * b11 + b12 * b12;
  const double c22 = b02 * b02 + b12 * b12 + b22 * b22;
  const double c01 = b00 * b01 + b01 * b11 + b02 * b12;
  const double c02 = b00 * b02 + b01 * b12 + b02 * b22;
  const double c12 = b01 * b02 + b11 * b12 + b12 * b22;

  // p^2 = tr(B^2)/6, q = det(B)/2: eigenvalues m + 2p cos(phi + 2 pi k/3).
  const double p = std::sqrt((c00 + c11 + c22) / 6.0);
  const double q = 0.5 * (b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) +
                          b02 * (b01 * b12 - b11 * b02));

  // Discriminant as a sum of squares of the 3x3 minors of the 6x3 matrix whose rows are
  // (I, B, B^2) at the diagonal positions (weight 1) and the off-diagonal ones (weight sqrt 2).
  const double bo[3] = {b01, b02, b12}, co[3] = {c01, c02, c12};
  const double bd[3] = {b00, b11, b22}, cd[3] = {c00, c11, c22};
  double disc = 0.0;
  for (int a = 0; a < 3; ++a)  // one diagonal row + two off-diagonal rows (x3 diagonal choices)
    for (int b = a + 1; b < 3; ++b) {
      const double mnr = bo[a] * co[b] - bo[b] * co[a];
      disc += 12.0 * mnr * mnr;
    }
  for (int i = 0; i < 3; ++i)  // two diagonal rows + one off-diagonal row
    for (int j = i + 1; j < 3; ++j)
      for (int o = 0; o < 3; ++o) {
        const double mnr = (bd[j] - bd[i]) * co[o] - (cd[j] - cd[i]) * bo[o];
        disc += 2.0 * mnr * mnr;
      }
  {  // three diagonal rows
    const double mnr = (b11 - b00) * (c22 - c00) - (b22 - b00) * (c11 - c00);
    disc += mnr * mnr;
  }

  // Eigenvalues without trigonometry. With t = (lambda - m)/p the characteristic polynomial is
  // t^3 - 3t - 2r, r = q/p^3 in [-1, 1], roots 2 cos(phi + 2 pi k/3). The root of largest
  // magnitude, |t| = ta in [sqrt 3, 2], is always simple (|t| >= sqrt 3 > the other two roots'
  // 1 + gap): Newton from a cubic fit of ta(|r|) (error 1.3e-4) reaches round-off in 2 steps.
  // The other pair is m - t/2 p +- gap/2 with gap^2 = disc / P'(lambda)^2,
  // P'(lambda) = 3 p^2 (ta^2 - 1) >= 6 p^2: its difference is then as accurate as disc, which is
  // what keeps D_sigma at round-off for double singular values.
  const double r = p > 0.0 ? std::clamp(q / (p * p * p), -1.0, 1.0) : 0.0;
  const double ra = std::abs(r);
  double ta = ((0.01874897 * ra - 0.08126101) * ra + 0.33042943) * ra + 1.73218504;
  for (int it = 0; it < 2; ++it)
    ta -= (ta * ta * ta - 3.0 * ta - 2.0 * ra) / (3.0 * (ta * ta - 1.0));
  const double gap = p > 0.0 ? std::sqrt(disc) / (3.0 * p * p * (ta * ta - 1.0)) : 0.0;
  const double mid = m - 0.5 * p * (r >= 0.0 ? ta : -ta);  // centre of the other pair
  // r >= 0: lambda1 = m + p ta is the isolated root; r < 0: lambda3 = m - p ta is.
  const double l1 = std::max(r >= 0.0 ? m + p * ta : mid + 0.5 * gap, 0.0);
  const double l2 = std::max(r >= 0.0 ? mid + 0.5 * gap : mid - 0.5 * gap, 0.0);
  const double s1 = std::sqrt(l1);
  double s2 = 0.0, s23 = 0.0;  // sigma2 and sigma2 * sigma3
  if (l2 < 1e-2 * l1) {
    Eigen::Matrix3d G;
    G << g00, b01, b02, b01, g11, b12, b02, b12, g22;
    const Eigen::Vector2d pair = detail::small_pair(gs, G, l1);
    s2 = std::min(std::sqrt(pair(0)), s1);
    s23 = pair(1);
  } else {
    s2 = std::min(std::sqrt(l2), s1);
    s23 = std::abs(gs.determinant()) / s1;
  }
  const double s3 = s2 > 0.0 ? std::min(s23 / s2, s2) : 0.0;
  const double up = normal ? detail::pow2(e) : std::ldexp(1.0, e);
  return Eigen::Vector3d(s1, s2, s3) * up;
}

}  // namespace valsalva::les
