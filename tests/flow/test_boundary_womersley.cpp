// Inflow building blocks: complex Bessel functions (real axis against std::cyl_bessel_j, the
// power series and Hankel's expansion agreeing where both hold on the Womersley ray), the
// Womersley profile (flux = Q(t) by quadrature, no slip, quasi-steady Poiseuille limit at low
// Wo), and the periodic CSV waveform (interpolation, wrap, errors naming file and line).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "flow/inflow_waveform.hpp"
#include "flow/womersley.hpp"

using namespace valsalva;

TEST_CASE("complex Bessel J0, J1 up to |z| = 30") {
  // On the real axis the series cancels worst (its terms sum to I0(x) ~ 3e5 at x = 15 while
  // |J0| < 1): 1e-10 absolute there; on the Womersley ray |J0| grows like the terms.
  for (double x : {0.5, 2.404825557695773, 7.0, 15.0, 17.9, 18.1, 28.0}) {
    CAPTURE(x);
    CHECK(std::abs(flow::bessel_j0({x, 0}) - std::cyl_bessel_j(0.0, x)) < 1e-10);
    CHECK(std::abs(flow::bessel_j1({x, 0}) - std::cyl_bessel_j(1.0, x)) < 1e-10);
  }
  // Kelvin functions ber(1) + i bei(1) = J0(i^{3/2}) (Abramowitz & Stegun table 9.12).
  const auto k1 = flow::bessel_j0(std::polar(1.0, 0.75 * std::numbers::pi));
  CHECK(k1.real() == doctest::Approx(0.9843817812).epsilon(1e-9));
  CHECK(k1.imag() == doctest::Approx(0.2495660400).epsilon(1e-9));
  // Across the switch at |z| = 18 on the Womersley ray the series and Hankel's expansion agree:
  // the jump from 18 - 1e-9 to 18 + 1e-9 is J0' dz = -J1 dz to first order.
  const auto ray = std::polar(1.0, 0.75 * std::numbers::pi);
  const auto below = flow::bessel_j0((18 - 1e-9) * ray), above = flow::bessel_j0((18 + 1e-9) * ray);
  MESSAGE("J0 at |z| = 18 on the ray: " << below << " vs " << above);
  const auto slope = -flow::bessel_j1(18.0 * ray) * ray * 2e-9;
  CHECK(std::abs(above - below - slope) / std::abs(above) < 1e-12);
}

TEST_CASE("Womersley profile: flux equals Q(t), no slip, Poiseuille at low Wo") {
  for (double wo : {4.0, 17.0, 20.0}) {
    CAPTURE(wo);
    const double R = 0.0125, period = 1.0;
    const double nu = R * R * 2 * std::numbers::pi / period / (wo * wo);
    const auto w = flow::Womersley::from_sine(R, nu, 1e-4, 2e-4, period, 0.3);
    CHECK(w.womersley_number() == doctest::Approx(wo));
    for (double t : {0.0, 0.3, 0.77}) {
      // Simpson quadrature of 2 pi r u over [0, R] with 2000 intervals.
      const int n = 2000;
      double flux = 0;
      for (int i = 0; i <= n; ++i) {
        const double r = R * i / n, c = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        flux += c * 2 * std::numbers::pi * r * w.velocity(r, t);
      }
      flux *= R / n / 3;
      const double q = 1e-4 + 2e-4 * std::sin(2 * std::numbers::pi * t / period + 0.3);
      CHECK(flux == doctest::Approx(q).epsilon(1e-8));
      CHECK(std::abs(w.velocity(R, t)) < 1e-12);
    }
  }
  // Wo -> 0: the profile is the quasi-steady Poiseuille profile of Q(t).
  const double R = 0.01;
  const auto slow = flow::Womersley::from_sine(R, 1.0, 0.0, 1e-4, 1e3, 0.0);
  const double t = 250;  // Q = 1e-4
  CHECK(slow.velocity(0.5 * R, t) ==
        doctest::Approx(2e-4 / (std::numbers::pi * R * R) * 0.75).epsilon(1e-6));
}

TEST_CASE("Womersley pressure gradient: the profile solves du/dt = G + nu (u'' + u'/r)") {
  // Central differences (step 1e-4 of R and of the period: truncation ~1e-8 relative, round-off
  // ~1e-16 / 1e-8 = 1e-8) at interior radii: the residual is 1e-5 of the terms' size at most;
  // a wrong G_h (a missing factor i w or the wrong flux factor) is off by O(1).
  for (double wo : {4.0, 17.0}) {
    const double R = 0.01, period = 1.0;
    const double nu = R * R * 2 * std::numbers::pi / period / (wo * wo);
    const auto w = flow::Womersley::from_sine(R, nu, 1e-5, 2e-5, period, 0.4);
    const double hr = 1e-4 * R, ht = 1e-4 * period;
    for (double s : {0.2, 0.6, 0.95})
      for (double t : {0.1, 0.55}) {
        CAPTURE(wo);
        CAPTURE(s);
        CAPTURE(t);
        const double r = s * R;
        const double dudt = (w.velocity(r, t + ht) - w.velocity(r, t - ht)) / (2 * ht);
        const double up = w.velocity(r + hr, t), u0 = w.velocity(r, t), um = w.velocity(r - hr, t);
        const double lap = (up - 2 * u0 + um) / (hr * hr) + (up - um) / (2 * hr) / r;
        const double g = w.pressure_gradient(t);
        const double scale = std::abs(dudt) + std::abs(g) + std::abs(nu * lap);
        CHECK(std::abs(dudt - g - nu * lap) < 1e-5 * scale);
      }
  }
  // Steady limit: Poiseuille's G = 8 nu Q / (pi R^4).
  const auto steady = flow::Womersley::from_sine(0.01, 1e-6, 1e-5, 0.0, 1.0, 0.0);
  CHECK(steady.pressure_gradient(0.3) ==
        doctest::Approx(8e-6 * 1e-5 / (std::numbers::pi * 1e-8)).epsilon(1e-12));
}

TEST_CASE("table waveform: periodic interpolation, mean, rows that are not one period") {
  const auto w = flow::table_waveform({0.0, 0.5, 1.0}, {1.0, 3.0, 1.0});
  CHECK(w.period == 1.0);
  CHECK(w(0.25) == doctest::Approx(2.0));
  CHECK(w(1.25) == doctest::Approx(2.0));
  CHECK(w(-0.75) == doctest::Approx(2.0));
  CHECK(w.mean == doctest::Approx(2.0));
  CHECK_THROWS_WITH_AS(flow::table_waveform({0.0}, {1.0}), doctest::Contains("found 1"),
                       flow::WaveformError);
  CHECK_THROWS_WITH_AS(flow::table_waveform({0.0, 0.5, 0.5}, {1.0, 2.0, 3.0}),
                       doctest::Contains("row 3: time 0.5 is not after"), flow::WaveformError);
}
