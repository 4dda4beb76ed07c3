// The body-force hook of ProjectionRK4 (f/rho added to the momentum right-hand side once per RK
// stage), on periodic hexahedral boxes at 1 and 2 ranks:
// - a uniform force accelerates a fluid at rest as u = f t / rho: convection and viscosity of a
//   uniform field vanish and its divergence is zero, so the only error is round-off;
// - a Kolmogorov forcing f = F sin(k y) e_x drives the shear flow
//     u = U_h (1 - exp(-nu k_h^2 t)) sin(k y_j),  U_h = F / (rho nu k_h^2),
//   k_h^2 = (2 - 2 cos(k h)) / h^2 the eigenvalue of the compact Laplacian on uniform hexahedra
//   (convection of a parallel shear flow vanishes discretely too); at the end it is steady and
//   within (k h)^2 / 12 of the continuous profile F / (rho nu k^2) sin(k y).
// The hook also receives the documented stage times t^n + {0, 1/4, 1/3, 1/2} dt.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/projection_rk4.hpp"

using namespace valsalva;
using Vec = Eigen::Vector3d;

namespace {

struct Box {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  // A slab with n cells along y (the shear direction) and 4 along x and z, h = 1/n.
  explicit Box(int n) {
    auto spec = test::periodic_box("hexa", n);
    spec.cells = {4, n, 4};
    spec.length = Vec(4.0 / n, 1.0, 4.0 / n);
    mesh = mesh::generate_box(spec);
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  }
};

flow::FlowState at_rest(const mesh::LocalMesh& m) {
  return {flow::VectorField(m.num_local(), Vec::Zero()), flow::ScalarField(m.num_local(), 0.0),
          0.0};
}

}  // namespace

TEST_CASE("a uniform body force accelerates the fluid as f t / rho to round-off") {
  Box box(8);
  const double rho = 1.3, dt = 0.01;
  const Vec f(0.7, -0.2, 0.4);
  flow::ProjectionOptions options;
  options.density = rho;
  options.viscosity = 0.01;
  flow::ProjectionRK4 solver(box.local, options);
  std::vector<double> stage_times;
  solver.set_body_force([&](int, double t, const flow::VectorField&, flow::VectorField& out) {
    if (stage_times.size() < 4) stage_times.push_back(t);
    for (auto& v : out) v = f;
  });
  auto state = at_rest(box.local);
  for (int step = 0; step < 50; ++step) solver.step(state, dt);
  double worst = 0;
  for (int i = 0; i < box.local.num_owned; ++i)
    worst = std::max(worst, (state.velocity[i] - f * state.time / rho).norm());
  worst = box.local.comm.max(worst);
  MESSAGE("uniform force: max |u - f t / rho| = " << worst << " at t = " << state.time);
  CHECK(worst < 1e-12 * (f * state.time / rho).norm());
  REQUIRE(stage_times.size() == 4);
  const double expected[4] = {0, dt / 4, dt / 3, dt / 2};
  for (int k = 0; k < 4; ++k) CHECK(stage_times[k] == doctest::Approx(expected[k]).epsilon(1e-14));
}

TEST_CASE("Kolmogorov forcing converges to its steady shear profile") {
  const int n = 16;
  Box box(n);
  const double rho = 1.1, nu = 0.05, F = 0.3, h = 1.0 / n;
  const double k = 2 * std::numbers::pi, kh2 = (2 - 2 * std::cos(k * h)) / (h * h);
  const double U_h = F / (rho * nu * kh2), U = F / (rho * nu * k * k);
  flow::ProjectionOptions options;
  options.density = rho;
  options.viscosity = nu;
  flow::ProjectionRK4 solver(box.local, options);
  const auto& x = box.local.position;
  solver.set_body_force([&](int, double, const flow::VectorField&, flow::VectorField& out) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec(F * std::sin(k * x[i].y()), 0, 0);
  });
  auto state = at_rest(box.local);
  // dt = 0.01: nu k_max^2 dt = 0.05 * 12 * 256 * 0.01 = 1.5, inside RK4's 2.78 on the real axis.
  const double dt = 0.01;
  auto profile_error = [&](double amplitude) {
    double worst = 0;
    for (int i = 0; i < box.local.num_owned; ++i)
      worst = std::max(worst,
                       (state.velocity[i] - Vec(amplitude * std::sin(k * x[i].y()), 0, 0)).norm());
    return box.local.comm.max(worst);
  };
  while (state.time < 0.5 - 1e-12) solver.step(state, dt);
  // Transient: RK4 on this linear problem, time error ~ (lambda dt)^5 / 120 per step.
  const double transient = profile_error(U_h * (1 - std::exp(-nu * kh2 * state.time)));
  while (state.time < 5 - 1e-12) solver.step(state, dt);
  const double steady_discrete = profile_error(U_h);
  const double steady_continuous = profile_error(U);
  MESSAGE("Kolmogorov: transient error " << transient / U_h << ", steady vs discrete profile "
                                         << steady_discrete / U_h << ", vs continuous "
                                         << steady_continuous / U << " (U = " << U << ")");
  CHECK(transient < 1e-6 * U_h);
  // Remaining decay exp(-nu k_h^2 * 5) = 5.4e-5 of U_h.
  CHECK(steady_discrete < 1e-4 * U_h);
  CHECK(steady_continuous < 1.2 * (k * h) * (k * h) / 12 * U);
}
