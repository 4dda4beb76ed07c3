// The linearly implicit coupling (immersed.coupling = "implicit", ibm/implicit_markers.hpp) on
// the stretched neo-Hookean block relaxing in a periodic box of fluid at rest (ib_box.hpp):
// - at 2.5 times the explicit per-stage bound (where per_stage blows up: its measured limit is
//   1.2 times the bound, test_ib_stability) it runs, and the block relaxes to its reference shape
//   with the marker speeds decaying. Its own limit on this block lies between 3 and 4 times the
//   per-stage bound (measured: 3x runs 133 steps, 4x grows, 6x inverts an element): the solve
//   uses the unprojected fluid response, so it is not unconditionally stable;
// - below the bound it agrees with the explicit per_step coupling, the difference falling at
//   first order in dt (the backward-Euler force is first-order accurate);
// - 2 ranks give the markers of 1 rank to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "ib_box.hpp"

using namespace valsalva;

namespace {

test::IbBoxSpec block(ibm::CouplingMode mode) {
  test::IbBoxSpec spec;
  spec.mode = mode;
  spec.shear_modulus = 4.0;
  spec.cells = 12;
  spec.viscosity = 0.002;  // weak damping: the inertial (oscillator) limit of the explicit coupling
  return spec;
}

// Extent of the markers along x (the stretched direction; 0.3 at rest, 0.36 at the start).
double extent_x(const test::IbBox& box) {
  const auto& x = box.ib->positions();
  return x.row(0).maxCoeff() - x.row(0).minCoeff();
}

Eigen::Matrix3Xd run_to(ibm::CouplingMode mode, double dt, double end) {
  test::IbBox box(block(mode));
  const int steps = static_cast<int>(std::lround(end / dt));
  for (int n = 0; n < steps; ++n) box.step(dt);
  return box.ib->positions();
}

}  // namespace

TEST_CASE("the implicit coupling runs beyond the explicit bound and relaxes the block") {
  test::IbBox probe(block(ibm::CouplingMode::per_stage));
  const double bound = probe.ib->stable_time_step();
  const double dt = 2.5 * bound;
  bool explicit_failed = false;
  try {
    test::IbBox box(block(ibm::CouplingMode::per_stage));
    for (int n = 0; n < 160; ++n) box.step(dt);
    explicit_failed = !(box.ib->velocities().cwiseAbs().maxCoeff() < 1e3);
  } catch (const std::runtime_error&) {
    explicit_failed = true;  // an inverted element
  }
  CHECK(explicit_failed);

  test::IbBox box(block(ibm::CouplingMode::implicit));
  CHECK(std::isinf(box.ib->stable_time_step()));
  const double start = extent_x(box);
  double peak_speed = 0;
  for (int n = 0; n < 160; ++n) {
    box.step(dt);
    peak_speed = std::max(peak_speed, box.ib->velocities().cwiseAbs().maxCoeff());
  }
  const double end = extent_x(box);
  MESSAGE("dt " << dt << " s (2.5 x the per-stage bound " << bound << " s): extent " << start
                << " -> " << end << " m, BiCGSTAB iterations " << box.ib->last_implicit_iterations()
                << ", last speed " << box.ib->velocities().cwiseAbs().maxCoeff() << " of peak "
                << peak_speed);
  // Relaxed by more than half of its initial stretch (0.06 m), and not beyond the reference
  // shape by more than a tenth of it (no overshoot from an undamped oscillation).
  CHECK(start - end > 0.03);
  CHECK(end > 0.3 - 0.006);
  CHECK(box.ib->velocities().cwiseAbs().maxCoeff() < 0.5 * peak_speed);
  CHECK(box.ib->last_min_det() > 0.5);
}

TEST_CASE("below the explicit bound the implicit coupling converges to the explicit one") {
  test::IbBox probe(block(ibm::CouplingMode::per_step));
  const double bound = probe.ib->stable_time_step();
  const double end = 8 * bound;
  const auto reference = run_to(ibm::CouplingMode::per_step, bound / 16, end);
  const auto displacement = (reference - probe.ib->positions()).cwiseAbs().maxCoeff();
  double previous = 0;
  for (int k : {4, 8}) {
    const double dt = bound / k;
    const double error =
        (run_to(ibm::CouplingMode::implicit, dt, end) - reference).cwiseAbs().maxCoeff();
    MESSAGE("dt bound/" << k << ": |X_implicit - X_per_step(dt bound/16)| = " << error
                        << " m, of a displacement " << displacement << " m");
    CHECK(error < (k == 4 ? 0.1 : 0.05) * displacement);
    if (previous > 0) {
      // First order: halving dt halves the difference (the per_step reference has its own
      // first-order error at dt/16, half of the finer one's at most).
      CHECK(previous / error > 1.5);
      CHECK(previous / error < 2.8);
    }
    previous = error;
  }
}

TEST_CASE("the implicit coupling gives the same markers on 1 and 2 ranks") {
  const auto spec = block(ibm::CouplingMode::implicit);
  test::IbBox box(spec);
  const double dt = 0.02;
  for (int n = 0; n < 10; ++n) box.step(dt);
  CHECK(test::marker_difference_to_serial(spec, box, 10, dt) < 1e-10);
}
