// The time-step bound of the explicit coupling (ibm/ib_stability.hpp) against the measured
// limit: a stretched neo-Hookean block relaxing in a periodic box of fluid at rest, bisection on
// dt (unstable = an inverted element, or marker velocities growing tenfold over the run), in
// both coupling modes. Asserted: the bound is safe (dt just below it runs) and not more than a
// factor 2 below the measured limit. Measured with 60 steps and 6 bisections (ratio measured /
// bound): per-stage G 1 h 1/12: 0.139 / 0.101 s (1.38); G 4 h 1/12: 0.0608 / 0.0506 (1.20);
// G 4 h 1/16: 0.0436 / 0.0354 (1.23); per-step G 4 h 1/12: 0.0492 / 0.0358 (1.38).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "ib_box.hpp"

using namespace valsalva;

namespace {

bool runs_stably(const test::IbBoxSpec& spec, double dt, int steps) {
  test::IbBox box(spec);
  try {
    box.step(dt);
    box.step(dt);
    const double v0 = box.ib->velocities().cwiseAbs().maxCoeff();
    for (int n = 2; n < steps; ++n) box.step(dt);
    const double v1 = box.ib->velocities().cwiseAbs().maxCoeff();
    return std::isfinite(v1) && v1 < 10 * v0;
  } catch (const std::runtime_error&) {
    return false;  // an inverted element: the coupling blew up
  }
}

// Largest stable dt in [lo, hi] by bisection (lo assumed stable, hi unstable).
double measured_limit(const test::IbBoxSpec& spec, double lo, double hi, int steps) {
  for (int it = 0; it < 4; ++it) {
    const double mid = std::sqrt(lo * hi);
    (runs_stably(spec, mid, steps) ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace

TEST_CASE("the coupling's time-step bound is safe and close to the measured limit") {
  struct Row {
    ibm::CouplingMode mode;
    double G;
    int cells;
  };
  for (const Row& row :
       {Row{ibm::CouplingMode::per_stage, 1.0, 12}, Row{ibm::CouplingMode::per_stage, 4.0, 12},
        Row{ibm::CouplingMode::per_stage, 4.0, 16}, Row{ibm::CouplingMode::per_step, 4.0, 12}}) {
    test::IbBoxSpec spec;
    spec.mode = row.mode;
    spec.shear_modulus = row.G;
    spec.cells = row.cells;
    spec.viscosity = 0.002;  // weak damping: the inertial (oscillator) limit governs
    test::IbBox probe(spec);
    const double bound = probe.ib->stable_time_step();
    const int steps = 40;
    CHECK(runs_stably(spec, 0.95 * bound, steps));
    const double limit = measured_limit(spec, 0.95 * bound, 2.5 * bound, steps);
    MESSAGE(std::string(row.mode == ibm::CouplingMode::per_stage ? "per-stage" : "per-step")
            << " G " << row.G << " h 1/" << row.cells << ": bound " << bound << " s, measured "
            << limit << " s, ratio " << limit / bound);
    CHECK(limit >= 0.95 * bound);
    CHECK(limit <= 2.0 * bound);
  }
}
