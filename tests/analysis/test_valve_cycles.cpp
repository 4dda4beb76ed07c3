// Valve cycle indices (analysis/valve_cycles.hpp) on synthetic cycles with exact answers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/valve_cycles.hpp"

using namespace valsalva::analysis;

namespace {

// Q = Q0 sin(2 pi t) on [0, 1): forward volume Q0 / pi over the first half, backward the same
// over the second; the valve opens linearly from t = 0.1 to 0.2, stays open, closes linearly
// from 0.5 to 0.6 (ratio 0.4 when open); TPG = 5 sin(2 pi t) + 1.
ValveSample synthetic(double t) {
  const double q = 1e-4 * std::sin(2 * std::numbers::pi * t);
  double ratio = 0.4 * std::clamp((t - 0.1) / 0.1, 0.0, 1.0);
  if (t > 0.5) ratio = 0.4 * std::clamp((0.6 - t) / 0.1, 0.0, 1.0);
  return {t, q, 5 * std::sin(2 * std::numbers::pi * t) + 1, ratio, 1e6 * (1 + t)};
}

}  // namespace

TEST_CASE("a cycle's volumes, instants and TPG extremes") {
  const int n = 4000;
  std::vector<ValveSample> s;
  for (int i = 0; i <= n; ++i) s.push_back(synthetic(double(i) / n));
  const CycleSummary c = summarise_cycle(0, s, CycleOptions{});
  const double exact = 1e-4 / std::numbers::pi;
  // Trapezoid error on a sine of n samples: relative (pi / n)^2 / 6 = 1e-7.
  CHECK(c.forward_volume == doctest::Approx(exact).epsilon(1e-6));
  CHECK(c.regurgitant_volume == doctest::Approx(exact).epsilon(1e-6));
  // Closing: the first sample after the opening peak at or below 0.05 x 0.4 (t = 0.595);
  // backflow before it: int_0.5^0.595 of -Q = Q0 / (2 pi) (1 - cos(2 pi 0.095)).
  // Instants are sample times: within one sample spacing of the exact crossing.
  const double spacing = 1.0 / n + 1e-12;
  CHECK(std::abs(c.closing - 0.595) <= spacing);
  const double closing =
      1e-4 / (2 * std::numbers::pi) * (1 - std::cos(2 * std::numbers::pi * 0.095));
  // The split moves with the closing sample: one spacing of backflow, |Q| <= Q0.
  CHECK(std::abs(c.closing_volume - closing) <= 1e-4 * spacing);
  CHECK(std::abs(c.leakage_volume - (exact - closing)) <= 1e-4 * spacing);
  CHECK(std::abs(c.opening_start - 0.105) <= spacing);
  CHECK(std::abs(c.fully_open - 0.19) <= spacing);
  CHECK(c.max_opening_ratio == doctest::Approx(0.4));
  CHECK(c.tpg_max == doctest::Approx(6.0).epsilon(1e-6));
  CHECK(c.tpg_min == doctest::Approx(-4.0).epsilon(1e-6));
  CHECK(c.max_von_mises == doctest::Approx(2e6));
}

TEST_CASE("a sign change inside an interval is split at the crossing") {
  // Q from +1 to -3 over [0, 1]: crossing at 0.25; forward 1 x 0.25 / 2, backward 3 x 0.75 / 2.
  const std::vector<ValveSample> s{{0, 1, 0, 0, 0}, {1, -3, 0, 0, 0}};
  const auto c = summarise_cycle(0, s, CycleOptions{});
  CHECK(c.forward_volume == doctest::Approx(0.125));
  CHECK(c.regurgitant_volume == doctest::Approx(1.125));
  CHECK(std::isnan(c.closing));  // never opened
  CHECK(c.leakage_volume == 0);
}

TEST_CASE("the tracker closes each cycle at its boundary sample and survives a checkpoint") {
  CycleOptions o;
  o.period = 1;
  o.start_time = 0.5;
  CycleTracker tracker(o);
  std::vector<CycleSummary> done;
  for (int i = 0; i <= 2500; ++i) {
    const double t = i * 1e-3;
    if (i == 1700) {  // checkpoint and restore mid-cycle
      CycleTracker fresh(o);
      fresh.restore(tracker.state());
      tracker = fresh;
    }
    ValveSample s = synthetic(t - 0.5 - std::floor(t - 0.5));  // the cycle's phase
    s.time = t;
    if (auto c = tracker.add(s)) done.push_back(*c);
  }
  REQUIRE(done.size() == 2);  // [0.5, 1.5) and [1.5, 2.5]
  CHECK(done[0].cycle == 0);
  CHECK(done[1].cycle == 1);
  CHECK(done[0].samples == 1001);
  CHECK(done[1].samples == 1001);
  CHECK(done[1].forward_volume == doctest::Approx(1e-4 / std::numbers::pi).epsilon(1e-5));
  CHECK_THROWS_AS(tracker.restore(std::vector<double>(7, 0.0)), std::invalid_argument);
  CHECK_THROWS_AS(CycleTracker(CycleOptions{0, 0, 0.05, 0.9}), std::invalid_argument);
}

TEST_CASE("instants count from the closed orifice when a clearance keeps it open") {
  // The same cycle with the leaflets held apart: the opening ratio never falls below 0.1 (a
  // closed orifice of 0.1, as a contact clearance leaves), the open one is 0.5. The instants
  // are fractions of the swing 0.1 -> 0.5, so they are those of the clean cycle.
  const int n = 4000;
  std::vector<ValveSample> s;
  for (int i = 0; i <= n; ++i) {
    auto sample = synthetic(double(i) / n);
    sample.opening_ratio += 0.1;
    s.push_back(sample);
  }
  const CycleSummary c = summarise_cycle(0, s, CycleOptions{});
  const double spacing = 1.0 / n + 1e-12;
  CHECK(std::abs(c.opening_start - 0.105) <= spacing);
  CHECK(std::abs(c.fully_open - 0.19) <= spacing);
  CHECK(std::abs(c.closing - 0.595) <= spacing);
  CHECK(c.min_opening_ratio == doctest::Approx(0.1));
  CHECK(c.max_opening_ratio == doctest::Approx(0.5));
}
