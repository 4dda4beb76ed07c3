// What bounds an adaptive time step (run::RunLoop::choose_dt).
// 1. An LES run on a mesh of unequal cells: each node's own nu + nu_sgs bounds its viscous rate,
// so a large subgrid viscosity in coarse cells does not pair with the smallest cells elsewhere.
// Periodic box whose x spacing varies 9:1 (x -> x + 0.8 sin x on [0, 2 pi]), a prescribed
// nu_sgs = 100 nu where the cells are coarse and 0 where they are fine, the fluid nearly at rest so
// that the Fourier target sets dt.
// 2. A coupling's bound (an immersed structure) caps the step before the check against the flow's
// stability limit: CFL and Fourier targets whose step it cuts anyway run.
// Runs at np 1 and 2.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "flow/run_diagnostics.hpp"
#include "mesh/box_generator.hpp"
#include "run/run_loop.hpp"

using namespace valsalva;

namespace {

constexpr double nu = 0.01;
constexpr double two_pi = 2 * std::numbers::pi;

struct StretchedBox {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  explicit StretchedBox(MPI_Comm comm) {
    mesh::BoxSpec box;
    box.cells = {24, 4, 4};
    box.length = Eigen::Vector3d(two_pi, two_pi / 6, two_pi / 6);
    box.periodic = {true, true, true};
    mesh = mesh::generate_box(box);
    // dx'/dx = 1 + 0.8 cos x: cells 1.8 / 0.2 = 9 times wider near x = 0 than near x = pi.
    for (auto& p : mesh.nodes) p.x() += 0.8 * std::sin(p.x());
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, comm);
  }
};

// 100 nu in the coarse cells (within 1.7 of x = 0, where dx'/dx > 1.4), none elsewhere.
double prescribed_nu_sgs(const Eigen::Vector3d& x) {
  return std::min(x.x(), two_pi - x.x()) < 1.7 ? 100 * nu : 0.0;
}

}  // namespace

TEST_CASE("LES time step: each node's nu + nu_sgs over its own h^2, not the largest nu_sgs") {
  StretchedBox box(MPI_COMM_WORLD);
  const auto& local = box.local;
  scene::RunOptions o;
  o.projection.density = 1.0;
  o.projection.viscosity = nu;
  o.initial = {flow::InitialType::taylor_green, 1e-6, 1.0};  // at rest for the CFL target
  o.time.end = 1e9;
  o.time.max_steps = 2;
  o.time.fourier = 0.05;  // its RK4 limit on these flat cells (h = cube root of V) is 0.08
  o.output.print = false;
  o.projection.subgrid_viscosity = [&local](int, const flow::TensorField& grad,
                                            flow::ScalarField& nu_sgs) {
    nu_sgs.resize(grad.size());
    for (std::size_t i = 0; i < grad.size(); ++i) nu_sgs[i] = prescribed_nu_sgs(local.position[i]);
  };
  run::RunLoop loop(box.mesh, box.metrics, local, o);
  const auto summary = loop.run();
  REQUIRE(summary.steps == 2);

  // Step 1 has no nu_sgs yet (nu alone); step 2 the prescribed field of step 1's stages, as
  // flow::stability_rates bounds a nodal viscosity (each node's neighbourhood).
  flow::ScalarField nu_total(local.num_local());
  for (int j = 0; j < local.num_local(); ++j)
    nu_total[j] = nu + prescribed_nu_sgs(local.position[j]);
  std::vector<double> scratch;
  const auto& weights = loop.solver().laplacian_weights();
  const auto& u = loop.state().velocity;
  const double rate_first = flow::stability_rates(local, weights, nu, u, scratch).viscous;
  const double rate_nodal = flow::stability_rates(local, weights, nu_total, u, scratch).viscous;
  const double dt1 = o.time.fourier / rate_first, dt2 = o.time.fourier / rate_nodal;
  CHECK(summary.time == doctest::Approx(dt1 + dt2).epsilon(1e-6));

  double h_min = 1e300, h_coarse_sgs = 1e300;
  for (int j = 0; j < local.num_owned; ++j) {
    h_min = std::min(h_min, local.h[j]);
    if (prescribed_nu_sgs(local.position[j]) > 0) h_coarse_sgs = std::min(h_coarse_sgs, local.h[j]);
  }
  h_min = local.comm.min(h_min);
  h_coarse_sgs = local.comm.min(h_coarse_sgs);
  // The nu_sgs field must leave the finest cells out, or the test shows nothing.
  REQUIRE(h_coarse_sgs > 1.4 * h_min);
  // The earlier bound, nu + max nu_sgs over the smallest h^2, gives a far smaller step.
  const double dt_global_max = o.time.fourier * h_min * h_min / (101 * nu);
  MESSAGE("dt with nodal nu + nu_sgs " << dt2 << " s, with the largest nu_sgs " << dt_global_max);
  CHECK(dt2 > 1.9 * dt_global_max);
}

TEST_CASE("a coupling's time-step bound caps targets beyond the flow's stability limit") {
  StretchedBox box(MPI_COMM_WORLD);
  scene::RunOptions o;
  o.projection.density = 1.0;
  o.projection.viscosity = nu;
  o.initial = {flow::InitialType::taylor_green, 1.0, 1.0};
  o.time.end = 1e9;
  o.time.max_steps = 3;
  o.time.cfl = 5;  // both beyond the RK4 limit (2 sqrt 2, 0.08 here): refused without a cap
  o.time.fourier = 0.5;
  o.output.print = false;
  CHECK_THROWS_WITH_AS(run::RunLoop(box.mesh, box.metrics, box.local, o).run(),
                       doctest::Contains("lower time.cfl or time.fourier"), run::RunError);
  const double cap = 1e-3;  // far below the limit
  o.coupling.max_dt = [cap](std::int64_t) { return cap; };
  o.coupling.max_dt_source = "a test bound";
  const auto summary = run::RunLoop(box.mesh, box.metrics, box.local, o).run();
  CHECK(summary.steps == 3);
  CHECK(summary.time == doctest::Approx(3 * cap).epsilon(1e-12));
}
