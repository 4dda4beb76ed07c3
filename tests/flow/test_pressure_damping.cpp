// ProjectionOptions::pressure_damping on the mode it exists for: the odd-even (checkerboard)
// pressure p = (-1)^(i+j+k) on a periodic box of uniform hexahedra, fluid at rest. The wide
// (median-dual) gradient of that mode is zero, so without the damping the step sees no force
// and no divergence: p stays as it is, exactly. With it the Poisson right-hand side gains
// div(grad p) - lap(p) = -lap(p) (compact Laplacian), so dp = -p up to a constant: one step
// leaves a uniform pressure and the fluid at rest (to the Poisson tolerance).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "field_test_utils.hpp"
#include "flow/boundary_conditions.hpp"
#include "flow/projection_rk4.hpp"

using namespace valsalva;

TEST_CASE("pressure damping removes the odd-even pressure mode in one step, and only with it") {
  const int n = 8;  // even: the checkerboard is periodic
  const auto local = test::local_box(test::periodic_box("hexa", n));
  const double h = 1.0 / n;
  for (bool damping : {true, false}) {
    CAPTURE(damping);
    flow::ProjectionOptions options;
    options.density = 1.2;
    options.viscosity = 0.01;
    options.poisson.tolerance = 1e-12;
    // No patch needs a condition on the periodic box; the damping term runs with conditions.
    options.boundary = std::make_shared<flow::BoundaryConditions>(
        local, std::vector<flow::BoundarySpec>{}, options.viscosity);
    options.pressure_damping = damping;
    flow::ProjectionRK4 solver(local, options);
    flow::FlowState state{flow::VectorField(local.num_local(), Eigen::Vector3d::Zero()),
                          flow::ScalarField(local.num_local(), 0.0), 0.0};
    for (int i = 0; i < local.num_local(); ++i) {
      const auto& x = local.position[i];
      const long parity = std::lround(x.x() / h) + std::lround(x.y() / h) + std::lround(x.z() / h);
      state.pressure[i] = parity % 2 == 0 ? 1.0 : -1.0;
    }
    const auto p0 = state.pressure;
    solver.step(state, 0.01);
    double lo = 1e300, hi = -1e300, change = 0, speed = 0;
    for (int i = 0; i < local.num_owned; ++i) {
      lo = std::min(lo, state.pressure[i]), hi = std::max(hi, state.pressure[i]);
      change = std::max(change, std::abs(state.pressure[i] - p0[i]));
      speed = std::max(speed, state.velocity[i].norm());
    }
    const double spread = local.comm.max(hi) + local.comm.max(-lo);
    change = local.comm.max(change), speed = local.comm.max(speed);
    MESSAGE("damping " << damping << ": pressure spread " << spread << ", max |p - p0| " << change
                       << ", max |u| " << speed);
    if (damping) {
      CHECK(spread < 1e-8);  // from 2: the mode is gone
    } else {
      CHECK(change < 1e-14);  // untouched: the wide operators do not see it
    }
    CHECK(speed < 1e-10);
  }
}
