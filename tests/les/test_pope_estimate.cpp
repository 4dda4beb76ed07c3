// Pope's subgrid energy estimate (les/pope_estimate.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <stdexcept>

#include "les/pope_estimate.hpp"

using namespace valsalva::les;

TEST_CASE("Pope estimate: hand value and inverse") {
  // Delta / (pi L) = 1/8: (1/8)^(2/3) = 1/4, k_sgs/k = 1.5 * 1.5 / 4 = 0.5625.
  const double L = 0.05;
  CHECK(pope_subgrid_fraction(std::numbers::pi * L / 8, L) ==
        doctest::Approx(0.5625).epsilon(1e-14));
  CHECK(pope_subgrid_fraction(std::numbers::pi * L / 8, L, 1.6) ==
        doctest::Approx(0.6).epsilon(1e-14));
  for (double f : {0.05, 0.2, 0.5})
    CHECK(pope_subgrid_fraction(pope_filter_width(f, L), L) == doctest::Approx(f).epsilon(1e-13));
  // 80 % resolved (f = 0.2) needs Delta = pi L (0.2/2.25)^(3/2) = 0.0833 L, i.e. L / Delta = 12.
  CHECK(L / pope_filter_width(0.2, L) == doctest::Approx(12.0).epsilon(5e-3));
  CHECK_THROWS_AS(pope_subgrid_fraction(0.0, L), std::invalid_argument);
  CHECK_THROWS_AS(pope_subgrid_fraction(1e-3, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(pope_filter_width(0.0, L), std::invalid_argument);
}

TEST_CASE("Pope estimate equals the integral of the inertial spectrum beyond pi/Delta") {
  // E = C eps^(2/3) kappa^(-5/3), eps = k^(3/2)/L; integrate numerically from pi/Delta to
  // 1e12 pi/Delta (trapezoid in log kappa, 20000 intervals; the neglected tail is 1e-8 of the
  // total) and divide by k.
  const double C = 1.5, k = 0.37, L = 0.021, eps = std::pow(k, 1.5) / L;
  for (double delta : {1e-4, 1e-3, 5e-3}) {
    const double kc = std::numbers::pi / delta;
    const int n = 20000;
    const double span = std::log(1e12);
    double ksgs = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double kappa = kc * std::exp(span * i / n);
      const double f =
          C * std::cbrt(eps * eps) * std::pow(kappa, -5.0 / 3.0) * kappa;  // dk = k dlnk
      ksgs += (i == 0 || i == n ? 0.5 : 1.0) * f * span / n;
    }
    CHECK(ksgs / k == doctest::Approx(pope_subgrid_fraction(delta, L, C)).epsilon(1e-6));
  }
}
