// Packs of doubles (GCC/Clang vector extension) and element-wise log and exp on them, for the
// batched explicit force kernel. Plain SSE2 code on x86-64 (no machine-specific flags): the
// compiler maps each pack operation onto 128-bit instructions.
//
// log and exp follow the algorithms of fdlibm e_log.c and e_exp.c (Sun Microsystems 1993, the
// basis of most libm implementations; error below 1 ulp): argument reduction x = 2^k m and
// x = k ln2 + r, then the same minimax polynomials. Arguments outside the range where the
// reduction is valid (log: not a positive normal number; exp: |x| >= 700, NaN) are passed lane
// by lane to std::log / std::exp, so special values behave exactly as in libm.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace valsalva::structure::simd {

constexpr int kLanes = 2;  // one SSE2 register of doubles
using Vd = double __attribute__((vector_size(kLanes * sizeof(double))));
using Vi = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

inline Vd splat(double a) {
  return Vd{} + a;
}
inline Vd vmin(Vd a, Vd b) {
  return a < b ? a : b;
}
inline bool all_lanes(Vi mask) {
  for (int l = 0; l < kLanes; ++l)
    if (!mask[l]) return false;
  return true;
}
inline Vd as_double(Vi v) {
  return std::bit_cast<Vd>(v);
}
inline Vi as_int(Vd v) {
  return std::bit_cast<Vi>(v);
}

// Natural logarithm (fdlibm __ieee754_log).
inline Vd vlog(Vd x) {
  if (!all_lanes(x >= 0x1p-1022 && x <= 0x1.fffffffffffffp1023)) {
    Vd r;
    for (int l = 0; l < kLanes; ++l) r[l] = std::log(x[l]);
    return r;
  }
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  constexpr double Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01,
                   Lg3 = 2.857142874366239149e-01, Lg4 = 2.222219843214978396e-01,
                   Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01,
                   Lg7 = 1.479819860511658591e-01;
  // x = 2^k m with m in [sqrt(2)/2, sqrt(2)).
  const Vi bits = as_int(x);
  Vi k = ((bits >> 52) & 0x7ff) - 1023;
  Vd m = as_double((bits & 0x000fffffffffffffLL) | 0x3ff0000000000000LL);
  const Vi big = m > 1.4142135623730951;  // -1 where m >= sqrt(2)
  m = big ? 0.5 * m : m;
  k -= big;
  // int64 -> double without cvtqq2pd (not in SSE2): add the pattern of 1.5 * 2^52.
  const Vd dk = as_double(k + 0x4338000000000000LL) - 0x1.8p52;
  const Vd f = m - 1.0;
  const Vd s = f / (2.0 + f);
  const Vd z = s * s, w = z * z;
  const Vd t1 = w * (Lg2 + w * (Lg4 + w * Lg6));
  const Vd t2 = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
  const Vd R = t2 + t1;
  const Vd hfsq = 0.5 * f * f;
  return dk * ln2_hi - ((hfsq - (s * (hfsq + R) + dk * ln2_lo)) - f);
}

// Exponential (fdlibm __ieee754_exp).
inline Vd vexp(Vd x) {
  if (!all_lanes(x > -700.0 && x < 700.0)) {
    Vd r;
    for (int l = 0; l < kLanes; ++l) r[l] = std::exp(x[l]);
    return r;
  }
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10,
                   inv_ln2 = 1.44269504088896338700e+00;
  constexpr double P1 = 1.66666666666666019037e-01, P2 = -2.77777777770155933842e-03,
                   P3 = 6.61375632143793436117e-05, P4 = -1.65339022054652515390e-06,
                   P5 = 4.13813679705723846039e-08;
  // k = nearest integer to x / ln 2 (round to nearest through the 1.5 * 2^52 shift).
  const Vd shifted = x * inv_ln2 + 0x1.8p52;
  const Vd dk = shifted - 0x1.8p52;
  const Vi k = as_int(shifted) - 0x4338000000000000LL;
  const Vd hi = x - dk * ln2_hi, lo = dk * ln2_lo;
  const Vd r = hi - lo;
  const Vd t = r * r;
  const Vd c = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))));
  const Vd y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
  // y * 2^k by adding k to the exponent field (|k| <= 1010 here, no overflow or subnormal).
  return as_double(as_int(y) + (k << 52));
}

}  // namespace valsalva::structure::simd
