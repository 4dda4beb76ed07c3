// The elastica reference of the closed valve's central fold (validation/valve_closure/
// corner_fold.hpp) against the small-slope beam and its own force balance.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "validation/valve_closure/corner_fold.hpp"

using valsalva::validation::corner_fold;
using valsalva::validation::CornerFoldInput;

namespace {

// The reference leaflet: neo-Hookean G 2.4 MPa, K 1.6 MPa (E = 4.8 MPa, nu = 0), t 0.15 mm, the
// closing pressure 12.4 kPa.
CornerFoldInput leaflet(double wedge, double tension = 0) {
  const double E = 4.8e6, t = 0.15e-3;
  return {E * t * t * t / 12, t, 12.4e3, wedge, tension};
}

}  // namespace

TEST_CASE("corner fold: a nearly flat corner is the simply supported beam") {
  // Turn of 1 degree at each support: slope p (2a)^3 / (24 D) = turn, so a = (3 D turn / p)^(1/3)
  // with a relative error of order turn^2 (3e-4); the sag p (2a)^4 * 5 / (384 D) below the
  // supports' chord, likewise.
  const double turn = M_PI / 180;
  const CornerFoldInput in = leaflet(M_PI - 2 * turn);
  const auto f = corner_fold(in);
  const double a = std::cbrt(3 * in.bending_stiffness * turn / in.pressure);
  CHECK(f.half_span == doctest::Approx(a).epsilon(1e-3));
  // The mid-surface's symmetry point lies below the supports by the sag; the supports lie
  // (t / 2) / cos(turn) above the corner's plane... measured through the corner distance: the
  // mid-surface point is (a tan(turn) - sag) + (t / 2) / cos(turn) above the corner.
  const double sag = 5 * in.pressure * std::pow(2 * a, 4) / (384 * in.bending_stiffness);
  const double expected = a * std::tan(turn) - sag + in.thickness / 2 / std::cos(turn);
  CHECK(f.corner_to_mid == doctest::Approx(expected).epsilon(1e-3));
  CHECK(f.corner_to_face == doctest::Approx(f.corner_to_mid - in.thickness / 2).epsilon(1e-6));
}

TEST_CASE("corner fold: the 120-degree corner of a three-leaflet valve") {
  // Against the same equations integrated by scipy's adaptive RK45 (rtol 1e-11) and solved by
  // fsolve (a separate implementation, runs of 2026-12-06): half-span 0.5368531 mm, corner to
  // mid-surface 0.2051555 mm, uncovered 0.0401503 mm^2 per corner. Tolerance 1e-5: RK4 with
  // 2000 steps and the trapezoidal area over them are accurate to ~1e-7 (checked by halving).
  const CornerFoldInput in = leaflet(2 * M_PI / 3);
  const auto f = corner_fold(in), fine = corner_fold(in, 4000);
  CHECK(f.half_span == doctest::Approx(0.5368531e-3).epsilon(1e-5));
  CHECK(f.corner_to_mid == doctest::Approx(0.2051555e-3).epsilon(1e-5));
  CHECK(f.uncovered_area == doctest::Approx(0.0401503e-6).epsilon(1e-5));
  CHECK(std::abs(fine.uncovered_area / f.uncovered_area - 1) < 1e-6);
  CHECK(f.support_reaction > 0);
  // More tension bridges the corner more widely.
  const auto taut = corner_fold(leaflet(2 * M_PI / 3, 10.0));
  CHECK(taut.half_span > f.half_span);
  CHECK(taut.uncovered_area > f.uncovered_area);
}

TEST_CASE("corner fold: bad input is refused") {
  CHECK_THROWS_AS(corner_fold(leaflet(M_PI)), std::invalid_argument);
  CHECK_THROWS_AS(corner_fold(leaflet(1.0, -1.0)), std::invalid_argument);
}
