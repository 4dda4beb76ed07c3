// ProjectionOptions::pressure_damping on the mode it exists for: the odd-even (checkerboard)
// pressure p = (-1)^(i+j+k) on a periodic box of uniform hexahedra, fluid at rest. The wide
// (median-dual) gradient of that mode is zero, so without the damping the step sees no force
// and no divergence: p stays as it is, exactly. With it the Poisson right-hand side gains
// div(grad p) - lap(p) = -lap(p) (compact Laplacian), so dp = -p up to a constant: one step
// leaves a uniform pressure and the fluid at rest (to the Poisson tolerance).
// With damp_pressure_increment (poisson.damping = increment) the term acts on half the last
// increment, theta (p^n - p^{n-1}) with theta = 1/2, away from open boundaries (here:
// everywhere): an old mode (last increment zero) stays; a mode that is the last increment goes
// by the recursion a_{n+1} = a_n - (a_n - a_{n-1}) / 2: 1 -> 1/2 -> 3/4 (to 2/3, no period-2
// oscillation).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "field_test_utils.hpp"
#include "flow/boundary_conditions.hpp"
#include "flow/projection_rk4.hpp"

using namespace valsalva;

namespace {

constexpr int box_cells = 8;  // even: the checkerboard is periodic

// The fluid at rest on the periodic box with boundary conditions (none needed there; the
// damping term runs with conditions).
flow::ProjectionOptions damping_options(const mesh::LocalMesh& local) {
  flow::ProjectionOptions options;
  options.density = 1.2;
  options.viscosity = 0.01;
  options.poisson.tolerance = 1e-12;
  options.boundary = std::make_shared<flow::BoundaryConditions>(
      local, std::vector<flow::BoundarySpec>{}, options.viscosity);
  return options;
}

// The odd-even mode (-1)^(i+j+k) at every local node.
flow::ScalarField checkerboard(const mesh::LocalMesh& local) {
  const double h = 1.0 / box_cells;
  flow::ScalarField mode(local.num_local());
  for (int i = 0; i < local.num_local(); ++i) {
    const auto& x = local.position[i];
    const long parity = std::lround(x.x() / h) + std::lround(x.y() / h) + std::lround(x.z() / h);
    mode[i] = parity % 2 == 0 ? 1.0 : -1.0;
  }
  return mode;
}

}  // namespace

TEST_CASE("pressure damping removes the odd-even pressure mode in one step, and only with it") {
  const auto local = test::local_box(test::periodic_box("hexa", box_cells));
  for (bool damping : {true, false}) {
    CAPTURE(damping);
    auto options = damping_options(local);
    options.pressure_damping = damping;
    flow::ProjectionRK4 solver(local, options);
    flow::FlowState state{flow::VectorField(local.num_local(), Eigen::Vector3d::Zero()),
                          checkerboard(local), 0.0};
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

TEST_CASE("increment damping acts on half the last increment of the odd-even mode") {
  const auto local = test::local_box(test::periodic_box("hexa", box_cells));
  const auto mode = checkerboard(local);
  for (bool fresh : {false, true}) {
    CAPTURE(fresh);
    auto options = damping_options(local);
    options.damp_pressure_increment = true;
    flow::ProjectionRK4 solver(local, options);
    flow::FlowState state{flow::VectorField(local.num_local(), Eigen::Vector3d::Zero()), mode, 0.0};
    // fresh: the mode arrived in the last step (dp = p); otherwise it is old (dp = 0).
    if (fresh) solver.set_pressure_increment(mode);
    for (double expected : fresh ? std::vector<double>{0.5, 0.75} : std::vector<double>{1, 1}) {
      solver.step(state, 0.01);
      // The amplitude on the mode, up to the constant the Poisson solve leaves free.
      double amplitude = 0, mean = 0, worst = 0, speed = 0;
      for (int i = 0; i < local.num_owned; ++i)
        amplitude += state.pressure[i] * mode[i], mean += state.pressure[i];
      const double count = local.comm.sum(static_cast<double>(local.num_owned));
      amplitude = local.comm.sum(amplitude) / count, mean = local.comm.sum(mean) / count;
      for (int i = 0; i < local.num_owned; ++i) {
        worst = std::max(worst, std::abs(state.pressure[i] - mean - amplitude * mode[i]));
        speed = std::max(speed, state.velocity[i].norm());
      }
      CAPTURE(expected);
      CHECK(amplitude == doctest::Approx(expected).epsilon(1e-8));
      CHECK(local.comm.max(worst) < 1e-8);  // nothing but the mode and a constant
      CHECK(local.comm.max(speed) < 1e-10);
    }
  }
}
