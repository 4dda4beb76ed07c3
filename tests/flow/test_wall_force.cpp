// Force of the fluid on a wall: plane Poiseuille flow driven by a body force f between walls at
// y = 0 and y = H (periodic in x and z). Exact: each wall carries the shear force
// mu du/dy|wall * area = f H / 2 * Lx * Lz along x, and both together balance the body force.
#include <doctest/doctest.h>

#include <cmath>

#include "field_test_utils.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/wall_force.hpp"
#include "flow/wall_shear.hpp"

using namespace valsalva;

namespace {

// Plane Poiseuille flow u = f/(2 mu) y (H - y) e_x with p = 0 and body force f e_x on a
// [0, 2] x [0, 1] x [0, 0.5] box, walls ymin/ymax, periodic in x and z; everything the wall-force
// functions need, kept alive together.
struct PoiseuilleChannel {
  static constexpr double mu = 3.6e-3, rho = 1100, f = 2.0, height = 1.0;
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  flow::VectorField u, body;
  flow::ScalarField p;
  flow::TensorField g;
  std::vector<double> weights;
  flow::WallForceInput in;

  PoiseuilleChannel(const std::string& type, double perturbation, int n, bool periodic_x = true) {
    mesh::BoxSpec spec;
    spec.cell_type = mesh::parse_box_cell_type(type);
    spec.cells = {n, n, n};
    spec.length = Eigen::Vector3d(2.0, height, 0.5);
    spec.perturbation = perturbation;
    spec.periodic = {periodic_x, false, true};
    mesh = mesh::generate_box(spec);
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
    u.resize(local.num_local());
    body.assign(local.num_local(), Eigen::Vector3d(f, 0, 0));
    for (int i = 0; i < local.num_local(); ++i) {
      const double y = local.position[i].y();
      u[i] = Eigen::Vector3d(f / (2 * mu) * y * (height - y), 0, 0);
    }
    p.assign(local.num_local(), 0.0);
    flow::gradient(local, u, g);
    const bool tets = type == "tetra";
    weights = tets ? flow::poisson_weights(mesh, metrics, local) : flow::laplacian_weights(local);
    in.density = rho;
    in.dynamic_viscosity = mu;
    in.velocity = &u;
    in.pressure = &p;
    in.velocity_gradient = &g;
    in.laplacian_weights = &weights;
    in.stiffness_weights = tets;
    in.body_force = &body;
  }
  // Exact shear force on one wall: mu du/dy|wall * area = f H / 2 * Lx * Lz.
  static double exact_force() { return f * height / 2 * 2.0 * 0.5; }
};

Eigen::Vector3d poiseuille_wall_force(const std::string& type, double perturbation, int n,
                                      flow::WallForceMethod method, double& exact) {
  const PoiseuilleChannel c(type, perturbation, n);
  exact = PoiseuilleChannel::exact_force();
  return flow::wall_force(c.local, "ymin", c.in, method);
}

}  // namespace

TEST_CASE(
    "wall force, residual method: exact for plane Poiseuille flow on hexahedra and split "
    "tetrahedra") {
  double exact = 0;
  const auto hexa = poiseuille_wall_force("hexa", 0.0, 8, flow::WallForceMethod::residual, exact);
  MESSAGE("hexa residual force ", hexa.transpose(), " exact ", exact);
  // Two-point fluxes are exact for the quadratic profile on uniform hexahedra.
  CHECK(hexa.x() == doctest::Approx(exact).epsilon(1e-12));
  CHECK(std::abs(hexa.y()) < 1e-12 * exact);
  CHECK(std::abs(hexa.z()) < 1e-12 * exact);
  // Split tetrahedra with the P1 stiffness weights: the median-dual flux of the interpolated
  // quadratic is exact too. (On perturbed tetrahedra the interpolant of the exact solution is not
  // the discrete solution, whose interior residuals vanish, so this static test says nothing
  // there: the flow cases check the force of computed solutions.)
  for (int n : {6, 12}) {
    const auto tet = poiseuille_wall_force("tetra", 0.0, n, flow::WallForceMethod::residual, exact);
    MESSAGE("split tetra n = ", n, ": force ", tet.transpose(), " exact ", exact);
    CHECK(tet.x() == doctest::Approx(exact).epsilon(1e-11));
  }
}

TEST_CASE("wall force, surface method: first order on hexahedra (one-sided wall gradient)") {
  double exact = 0;
  const auto coarse = poiseuille_wall_force("hexa", 0.0, 8, flow::WallForceMethod::surface, exact);
  const auto fine = poiseuille_wall_force("hexa", 0.0, 16, flow::WallForceMethod::surface, exact);
  const double e1 = std::abs(coarse.x() / exact - 1), e2 = std::abs(fine.x() / exact - 1);
  MESSAGE("surface method relative errors n=8: ", e1, " n=16: ", e2);
  // One-sided gradient of a quadratic: error h/H exactly halves with h.
  CHECK(test::observed_order(e1, e2, 1.0 / 8, 1.0 / 16) == doctest::Approx(1.0).epsilon(0.05));
}

TEST_CASE("wall force: unknown patch is refused with the mesh's patch names") {
  mesh::BoxSpec spec;
  spec.cells = {3, 3, 3};
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  flow::VectorField u(local.num_local(), Eigen::Vector3d::Zero());
  flow::ScalarField p(local.num_local(), 0.0);
  flow::TensorField g(local.num_local(), Eigen::Matrix3d::Zero());
  flow::WallForceInput in;
  in.velocity = &u;
  in.pressure = &p;
  in.velocity_gradient = &g;
  CHECK_THROWS_WITH_AS(flow::wall_force(local, "cylinder", in, flow::WallForceMethod::surface),
                       doctest::Contains("patch 'cylinder' is not in the mesh"),
                       std::invalid_argument);
}

TEST_CASE("wall shear stress: plane Poiseuille wall nodes carry f H / 2 along x") {
  const PoiseuilleChannel c("hexa", 0.0, 6);
  const double f = PoiseuilleChannel::f;
  const auto tau = flow::wall_shear_stress(flow::wall_loads(c.local, "ymin", c.in));
  double worst = 0;
  for (const auto& t : tau) worst = std::max(worst, (t - Eigen::Vector3d(f / 2, 0, 0)).norm());
  MESSAGE(tau.size(), " wall nodes, max |tau - f H/2 e_x| = ", worst);
  CHECK(worst < 1e-12 * f);
}

TEST_CASE(
    "wall shear stress at nodes on two patches: the other patch's pressure load is not shear") {
  // Pressure-driven plane Poiseuille flow, p = p0 + G (Lx - x), in the same box with an inlet
  // (xmin) and an outlet (xmax) instead of periodic x: the rim nodes of wall ymin also carry the
  // inlet or outlet face, whose pressure force p0 A (along x, tangential to the wall) is no wall
  // shear. On uniform hexahedra every wall node, rims included, has tau = G H / 2 e_x exactly;
  // p0 = 30 kPa is the size of an arterial pressure, the error it made before was p0 A_inlet / A.
  PoiseuilleChannel c("hexa", 0.0, 6, false);
  const double gradient = PoiseuilleChannel::f, p0 = 3e4, length = 2.0;
  for (int i = 0; i < c.local.num_local(); ++i)
    c.p[i] = p0 + gradient * (length - c.local.position[i].x());
  c.in.body_force = nullptr;
  const auto loads = flow::wall_loads(c.local, "ymin", c.in);
  const auto tau = flow::wall_shear_stress(loads);
  double worst = 0;
  std::int64_t rims = 0;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double error = (tau[i] - Eigen::Vector3d(gradient / 2, 0, 0)).norm();
    worst = std::max(worst, error);
    const double x = c.local.position[loads[i].node].x();
    if (x < 1e-12 || x > length - 1e-12) ++rims;
  }
  MESSAGE(tau.size(), " wall nodes (", rims, " on a rim), max |tau - G H/2 e_x| = ", worst);
  CHECK(c.local.comm.sum(rims) == 2 * 6);  // both rims of the 6 x 6 wall, z periodic
  // Round-off of sums of p0-sized fluxes, far below the shear G H / 2 = 1 Pa.
  CHECK(worst < 1e-10 * p0);
}

TEST_CASE("TAWSS and OSI: steady stress gives OSI 0, a purely oscillatory one 1/2") {
  const double tau0 = 1.7, period = 0.8;
  const int steps = 64;
  flow::WallShearStatistics steady, oscillating;
  auto sine = [&](double t) {
    return Eigen::Vector3d(0, tau0 * std::sin(2 * M_PI * t / period), 0);
  };
  for (int n = 0; n < 3 * steps; ++n) {
    const double t = (n + 1) * period / steps, dt = period / steps;
    steady.add({Eigen::Vector3d(tau0, 0, 0)}, {Eigen::Vector3d(tau0, 0, 0)}, dt);
    oscillating.add({sine(t - dt)}, {sine(t)}, dt);
  }
  CHECK(steady.osi()[0] == doctest::Approx(0).epsilon(1e-14));
  CHECK(steady.tawss()[0] == doctest::Approx(tau0).epsilon(1e-14));
  CHECK(oscillating.osi()[0] == doctest::Approx(0.5).epsilon(1e-12));
  // Mean of |sin| = 2/pi; the trapezoidal rule on 64 samples per period (samples on the kinks
  // of |sin|) errs by about (2 pi / 64)^2 / 12 = 8e-4.
  CHECK(oscillating.tawss()[0] == doctest::Approx(2 * tau0 / M_PI).epsilon(2e-3));
  // Checkpoint round trip.
  flow::WallShearStatistics restored;
  restored.restore(oscillating.state());
  CHECK(restored.osi()[0] == oscillating.osi()[0]);
  CHECK(restored.duration() == oscillating.duration());
}

TEST_CASE("RRT = 1 / ((1 - 2 OSI) TAWSS): a mean plus a reversing oscillation; nan when zero") {
  // tau = tau0 (m + sin wt), m = 1/2: TAWSS = tau0 (2/pi) (sqrt(1 - m^2) + m asin m),
  // OSI = (1 - m tau0 / TAWSS) / 2, so (1 - 2 OSI) TAWSS = m tau0 (Himburg et al. 2004).
  const double tau0 = 1.7, period = 0.8, m = 0.5;
  const int steps = 64;
  const double tawss = tau0 * 2 / M_PI * (std::sqrt(1 - m * m) + m * std::asin(m));
  const double osi = 0.5 * (1 - m * tau0 / tawss);
  flow::WallShearStatistics s, zero;
  auto tau = [&](double t) {
    return Eigen::Vector3d(0, 0, tau0 * (m + std::sin(2 * M_PI * t / period)));
  };
  for (int n = 0; n < 3 * steps; ++n) {
    const double t = (n + 1) * period / steps, dt = period / steps;
    s.add({tau(t - dt)}, {tau(t)}, dt);
    zero.add({Eigen::Vector3d::Zero()}, {Eigen::Vector3d::Zero()}, dt);
  }
  // The trapezoidal rule sums the sine over whole periods to round-off: the mean vector, hence
  // RRT, is exact; TAWSS and OSI carry the rule's error at the kinks of |tau| (~1e-3).
  CHECK(s.rrt()[0] == doctest::Approx(1 / ((1 - 2 * osi) * tawss)).epsilon(1e-12));
  CHECK(s.rrt()[0] == doctest::Approx(1 / ((1 - 2 * s.osi()[0]) * s.tawss()[0])).epsilon(1e-12));
  CHECK(s.tawss()[0] == doctest::Approx(tawss).epsilon(2e-3));
  CHECK(std::isnan(zero.rrt()[0]));
}

TEST_CASE("TAWSS: the trapezoidal rule is 2nd order on uneven steps") {
  // tau = exp(t) over [0, 1] on steps alternating h and 3h: TAWSS = e - 1 exactly. Halving every
  // step quarters the error (the rectangle rule of before only halved it).
  auto error = [](int pairs) {
    flow::WallShearStatistics s;
    const double h = 1.0 / (4.0 * pairs);
    double t = 0;
    for (int k = 0; k < 2 * pairs; ++k) {
      const double dt = (k % 2 == 0 ? 1 : 3) * h;
      s.add({Eigen::Vector3d(std::exp(t), 0, 0)}, {Eigen::Vector3d(std::exp(t + dt), 0, 0)}, dt);
      t += dt;
    }
    return std::abs(s.tawss()[0] - (std::exp(1.0) - 1));
  };
  const double coarse = error(16), fine = error(32);
  MESSAGE("TAWSS errors " << coarse << ", " << fine);
  CHECK(std::log2(coarse / fine) == doctest::Approx(2).epsilon(0.02));
}
