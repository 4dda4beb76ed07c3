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

TEST_CASE("CSV waveform: periodic interpolation and errors naming file and line") {
  const auto dir = std::filesystem::temp_directory_path();
  const auto good = dir / "valsalva_waveform_good.csv";
  std::ofstream(good) << "# comment\nt,Q\n0.0, 1.0\n0.5, 3.0\n1.0, 1.0\n";
  const auto w = flow::read_waveform_csv(good);
  CHECK(w.period == 1.0);
  CHECK(w(0.25) == doctest::Approx(2.0));
  CHECK(w(1.25) == doctest::Approx(2.0));
  CHECK(w(-0.75) == doctest::Approx(2.0));
  CHECK(w.mean == doctest::Approx(2.0));
  const auto bad = dir / "valsalva_waveform_bad.csv";
  std::ofstream(bad) << "t,Q\n0.0,1.0\n0.5\n";
  CHECK_THROWS_WITH_AS(
      flow::read_waveform_csv(bad),
      doctest::Contains("valsalva_waveform_bad.csv:3: expected two finite numbers"),
      flow::WaveformError);
  std::ofstream(bad) << "0.0,1.0\n0.5,2.0\n0.5,3.0\n";
  CHECK_THROWS_WITH_AS(flow::read_waveform_csv(bad),
                       doctest::Contains("valsalva_waveform_bad.csv:3: time 0.5 is not after"),
                       flow::WaveformError);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}
