// Packed log and exp of structure/simd_math.hpp against the C library: within 1 ulp on random
// arguments across the ranges the neo-Hookean kernel sees and far beyond, and exactly the
// library's values for special arguments (handled lane by lane).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "structure/simd_math.hpp"

using namespace valsalva::structure::simd;

namespace {
// Distance in units of the last place of the reference value.
double ulps(double v, double ref) {
  return std::abs(v - ref) / std::abs(std::nextafter(ref, 2 * ref + 1) - ref);
}
}  // namespace

TEST_CASE("packed log and exp agree with std::log and std::exp to 1 ulp") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> wide(-700, 700), narrow(-0.5, 0.5);
  double worst_log = 0, worst_exp = 0;
  for (int i = 0; i < 200000; ++i) {
    Vd a, b;
    for (int l = 0; l < kLanes; ++l) {
      a[l] = (l % 2 ? narrow(rng) : wide(rng));
      b[l] = std::exp(a[l]);
    }
    const Vd la = vlog(b), ea = vexp(a);
    for (int l = 0; l < kLanes; ++l) {
      if (b[l] != 1) worst_log = std::max(worst_log, ulps(la[l], std::log(b[l])));
      worst_exp = std::max(worst_exp, ulps(ea[l], std::exp(a[l])));
    }
  }
  CHECK(worst_log <= 1.0);
  CHECK(worst_exp <= 1.0);
  CHECK(vlog(splat(1.0))[0] == 0.0);
  CHECK(vexp(splat(0.0))[0] == 1.0);
}

TEST_CASE("packed log and exp of special arguments equal the library's") {
  const double inf = std::numeric_limits<double>::infinity();
  const double args[] = {0.0, -1.0, 1e-310, inf, -inf, std::nan(""), 800.0, -800.0, 1e-300};
  for (double a : args) {
    CAPTURE(a);
    const Vd l = vlog(splat(a)), e = vexp(splat(a));
    for (int k = 0; k < kLanes; ++k) {
      CHECK((std::isnan(l[k]) ? std::isnan(std::log(a)) : l[k] == std::log(a)));
      CHECK((std::isnan(e[k]) ? std::isnan(std::exp(a)) : e[k] == std::exp(a)));
    }
  }
}
