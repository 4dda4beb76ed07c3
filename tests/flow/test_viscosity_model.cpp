// Non-Newtonian viscosity laws (flow/viscosity_model.hpp) and their use by the solver:
// - the shear rate sqrt(2 S:S) of simple shear, rotation and extension;
// - each law's limits and asymptotes (Carreau-Yasuda: mu_0 at rest, its power-law branch;
//   regularised Casson: Casson's flow curve where m gamma_dot >> 1, finite at rest; power law with
//   its floor) and the refusal of bad parameters, naming the parameter;
// - ProjectionRK4 with a Carreau-Yasuda fluid equals, to round-off, the full-stress run whose
//   nu_sgs hook supplies mu(gamma_dot) / rho from each RK stage's gradient (so the viscosity is
//   evaluated per stage), and differs clearly from a Newtonian run at mu_0;
// - viscosity_field() and the nodal stability bound: a constant field gives the Newtonian rates;
// - with an LES model (Smagorinsky) the viscosity is mu(gamma_dot) / rho + nu_sgs, to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/operators.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"
#include "flow/viscosity_model.hpp"
#include "les/subgrid_viscosity.hpp"

using namespace valsalva;
using flow::ViscosityLaw;
using flow::ViscosityModel;

namespace {
ViscosityModel cho_kensey() {
  ViscosityModel m;
  m.law = ViscosityLaw::carreau_yasuda;
  m.mu_0 = 0.056, m.mu_inf = 0.00345, m.lambda = 3.313, m.a = 2, m.n = 0.3568;
  return m;
}
ViscosityModel casson(double m_reg) {
  ViscosityModel m;
  m.law = ViscosityLaw::casson;
  m.yield_stress = 0.005, m.plastic_viscosity = 0.0035, m.regularisation = m_reg;
  return m;
}
// A 2D vortex u = U (sin kx cos ky, -cos kx sin ky) in a periodic 10 mm box of 12 x 12 x 3
// hexahedra on two METIS parts: shear rates of 0 to 2 k U = 12.6 1/s, blood density.
struct VortexBox {
  static constexpr double rho = 1060, U = 0.01;
  mesh::LocalMesh mesh;
  flow::FlowState initial;
  VortexBox() {
    mesh::BoxSpec spec = test::periodic_box("hexa", 12);
    spec.cells = {12, 12, 3};
    spec.length = Eigen::Vector3d(0.01, 0.01, 0.0025);
    const auto box = mesh::generate_box(spec);
    const auto metrics = mesh::compute_dual_metrics(box);
    mesh = mesh::distribute(box, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
    const double k = 2 * std::numbers::pi / 0.01;
    for (const auto& x : mesh.position) {
      initial.velocity.emplace_back(U * std::sin(k * x.x()) * std::cos(k * x.y()),
                                    -U * std::cos(k * x.x()) * std::sin(k * x.y()), 0.0);
      initial.pressure.push_back(0.0);
    }
  }
};
}  // namespace

TEST_CASE("shear rate sqrt(2 S:S)") {
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  g(0, 1) = 7.0;  // u = 7 y e_x: simple shear
  CHECK(flow::shear_rate(g) == doctest::Approx(7.0).epsilon(1e-15));
  g << 0, -3, 0, 3, 0, 0, 0, 0, 0;  // rigid rotation
  CHECK(flow::shear_rate(g) == 0.0);
  g = Eigen::Vector3d(2.0, -2.0, 0.0).asDiagonal();  // planar extension: 2 |e|
  CHECK(flow::shear_rate(g) == doctest::Approx(4.0).epsilon(1e-15));
}

TEST_CASE("Carreau-Yasuda: mu_0 at rest, mu_inf + power-law branch at high shear") {
  const auto m = cho_kensey();
  CHECK(flow::apparent_viscosity(m, 0.0) == doctest::Approx(0.056).epsilon(1e-15));
  // lambda gamma >> 1: mu - mu_inf -> (mu_0 - mu_inf) (lambda gamma)^(n - 1), relative error
  // (n - 1)/a (lambda gamma)^-a = 3e-9 at gamma = 1e4.
  const double g = 1e4;
  const double branch = (m.mu_0 - m.mu_inf) * std::pow(m.lambda * g, m.n - 1);
  CHECK((flow::apparent_viscosity(m, g) - m.mu_inf) / branch == doctest::Approx(1.0).epsilon(1e-8));
  // decreasing (n < 1)
  double last = 1e9;
  for (double x : {0.01, 0.1, 1.0, 10.0, 100.0, 1000.0}) {
    const double mu = flow::apparent_viscosity(m, x);
    CHECK(mu < last);
    CHECK(mu > m.mu_inf);
    last = mu;
  }
}

TEST_CASE("lowest_viscosity: the infimum over all shear rates (the 1e9-step rule's viscosity)") {
  flow::ViscosityModel pl;
  pl.law = ViscosityLaw::power_law;
  pl.consistency = 0.01, pl.shear_rate_min = 0.1;
  const auto shear_thickening = [&] {
    auto m = pl;
    m.n = 1.5;
    return m;
  }();
  const auto shear_thinning = [&] {
    auto m = pl;
    m.n = 0.5;
    return m;
  }();
  auto cy_thickening = cho_kensey();
  cy_thickening.n = 1.5;
  for (const auto& m : {cho_kensey(), cy_thickening, casson(1000.0), shear_thickening}) {
    const double low = flow::lowest_viscosity(m);
    CHECK(low > 0);
    double seen = 1e300;  // the sampled minimum approaches the infimum from above
    for (double g = 0; g<1e9; g = g> 0 ? 10 * g : 1e-9)
      seen = std::min(seen, flow::apparent_viscosity(m, g));
    CHECK(seen >= low * (1 - 1e-15));
    CHECK(seen == doctest::Approx(low).epsilon(2e-3));
  }
  CHECK(flow::lowest_viscosity(shear_thinning) == 0.0);  // thins without bound
  flow::ViscosityModel newtonian;
  newtonian.mu = 0.0035;
  CHECK(flow::lowest_viscosity(newtonian) == 0.0035);
}

TEST_CASE("viscosity_cap: the largest viscosity of a shear-thinning power law, 0 for the rest") {
  flow::ViscosityModel pl;
  pl.law = ViscosityLaw::power_law;
  pl.consistency = 0.035, pl.n = 0.5, pl.shear_rate_min = 0.5;
  const double cap = flow::viscosity_cap(pl);
  CHECK(cap == doctest::Approx(0.035 / std::sqrt(0.5)).epsilon(1e-15));
  CHECK(flow::apparent_viscosity(pl, 0.0) == cap);  // reached at rest and below the floor
  CHECK(flow::apparent_viscosity(pl, 0.25) == cap);
  for (double g = 1e-9; g < 1e9; g *= 10) CHECK(flow::apparent_viscosity(pl, g) <= cap);
  auto thickening = pl;
  thickening.n = 1.5;
  flow::ViscosityModel newtonian;
  newtonian.mu = 0.0035;
  for (const auto& m : {thickening, cho_kensey(), casson(1000.0), newtonian})
    CHECK(flow::viscosity_cap(m) == 0.0);  // their nodal viscosity sets the time step
}

TEST_CASE("Casson (Papanastasiou): Casson's flow curve where the fluid flows, finite at rest") {
  const auto m = casson(1000.0);
  for (double g : {0.1, 1.0, 10.0, 300.0}) {  // m g >= 100: exp(-m g) <= 4e-44
    const double tau = flow::apparent_viscosity(m, g) * g;
    CHECK(std::sqrt(tau) ==
          doctest::Approx(std::sqrt(0.005) + std::sqrt(0.0035 * g)).epsilon(1e-14));
  }
  const double root = std::sqrt(0.0035) + std::sqrt(0.005 * 1000.0);
  CHECK(flow::apparent_viscosity(m, 0.0) == doctest::Approx(root * root).epsilon(1e-15));
  // continuous at rest: the regularised term tends to tau_y m
  CHECK(flow::apparent_viscosity(m, 1e-12) == doctest::Approx(root * root).epsilon(1e-9));
  // no yield stress: Newtonian at mu_p
  auto newtonian = casson(0.0);
  newtonian.yield_stress = 0;
  CHECK(flow::apparent_viscosity(newtonian, 5.0) == doctest::Approx(0.0035).epsilon(1e-15));
}

TEST_CASE("power law with its shear-rate floor") {
  ViscosityModel m;
  m.law = ViscosityLaw::power_law;
  m.consistency = 0.2, m.n = 0.5, m.shear_rate_min = 0.01;
  CHECK(flow::apparent_viscosity(m, 4.0) == doctest::Approx(0.1).epsilon(1e-15));
  CHECK(flow::apparent_viscosity(m, 0.0) == doctest::Approx(2.0).epsilon(1e-15));
  CHECK(flow::apparent_viscosity(m, 1e-3) == doctest::Approx(2.0).epsilon(1e-15));
}

TEST_CASE("bad parameters are refused naming the parameter") {
  auto problem = [](const ViscosityModel& m) {
    const auto p = flow::viscosity_model_problem(m);
    return p ? p->parameter : std::string("none");
  };
  auto m = cho_kensey();
  CHECK(problem(m) == "none");
  m.mu_0 = 0.001;  // < mu_inf
  CHECK(problem(m) == "mu_0");
  m = cho_kensey(), m.n = 0;
  CHECK(problem(m) == "n");
  m = cho_kensey(), m.a = -1;
  CHECK(problem(m) == "a");
  m = cho_kensey(), m.mu_inf = -1e-3;
  CHECK(problem(m) == "mu_inf");
  m = cho_kensey(), m.lambda = std::nan("");
  CHECK(problem(m) == "lambda");
  CHECK(problem(casson(10.0)) == "none");
  CHECK(problem(casson(0.0)) == "regularisation");
  auto c = casson(10.0);
  c.plastic_viscosity = 0;
  CHECK(problem(c) == "plastic_viscosity");
  ViscosityModel p;
  p.law = ViscosityLaw::power_law;
  p.consistency = 1, p.n = 1.5, p.shear_rate_min = 0;
  CHECK(problem(p) == "shear_rate_min");
  p.shear_rate_min = 1, p.n = -0.5;
  CHECK(problem(p) == "n");
}

TEST_CASE("ProjectionRK4 with a Carreau-Yasuda fluid: mu(gamma_dot) per node and per RK stage") {
  const VortexBox vb;
  const auto& mesh = vb.mesh;
  const auto& initial = vb.initial;
  const double rho = VortexBox::rho, U = VortexBox::U;
  const auto cy = cho_kensey();
  flow::ProjectionOptions base;
  base.density = rho;
  base.poisson.tolerance = 1e-12;
  auto rheology = base;
  rheology.rheology = cy;
  auto hook = base;  // viscosity 0 + nu_sgs = mu(gamma_dot) / rho from each stage's gradient
  hook.subgrid_viscosity = [&](int, const flow::TensorField& grad, flow::ScalarField& nu) {
    for (std::size_t i = 0; i < grad.size(); ++i)
      nu[i] = flow::apparent_viscosity(cy, flow::shear_rate(grad[i])) / rho;
  };
  auto newtonian = base;  // mu_0, the viscosity at rest
  newtonian.viscosity = cy.mu_0 / rho;
  flow::ProjectionRK4 a(mesh, rheology), b(mesh, hook), c(mesh, newtonian);
  CHECK(a.variable_viscosity());
  CHECK_FALSE(c.variable_viscosity());
  // The nodal viscosity of the initial state, as the time step sees it.
  flow::TensorField grad;
  flow::gradient(mesh, initial.velocity, grad);
  const auto& field = a.viscosity_field(initial.velocity);
  double field_error = 0, lo = 1e9, hi = 0;
  for (int i = 0; i < mesh.num_owned; ++i) {
    const double expected = flow::apparent_viscosity(cy, flow::shear_rate(grad[i])) / rho;
    field_error = std::max(field_error, std::abs(field[i] - expected) / expected);
    lo = std::min(lo, field[i]), hi = std::max(hi, field[i]);
  }
  CHECK(mesh.comm.max(field_error) == 0.0);
  CHECK(mesh.comm.max(hi) > 2 * mesh.comm.min(lo));  // the viscosity does vary
  std::vector<double> scratch;
  const auto rates =
      flow::stability_rates(mesh, a.laplacian_weights(), field, initial.velocity, scratch);
  // The Fourier number uses the viscosity node j's row sees: the |a_jk|-weighted mean of its edge
  // viscosities (nu_j + nu_k) / 2 (flow/run_diagnostics.hpp), between its smallest and largest.
  const auto& weights = a.laplacian_weights();
  std::vector<double> weighted(mesh.num_local(), 0.0), weight(mesh.num_local(), 0.0);
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const double w = std::abs(weights[e]), nu_jk = 0.5 * (field[j] + field[k]);
    weighted[j] += w * nu_jk, weighted[k] += w * nu_jk;
    weight[j] += w, weight[k] += w;
  }
  double fourier_rate = 0, own_rate = 0;
  for (int i = 0; i < mesh.num_owned; ++i) {
    const double h2 = mesh.h[i] * mesh.h[i];
    fourier_rate = std::max(fourier_rate, weighted[i] / weight[i] / h2);
    own_rate = std::max(own_rate, field[i] / h2);
  }
  CHECK(rates.viscous == doctest::Approx(mesh.comm.max(fourier_rate)).epsilon(1e-14));
  // Close to the node's own viscosity for this smooth field.
  CHECK(rates.viscous == doctest::Approx(mesh.comm.max(own_rate)).epsilon(0.1));
  flow::ScalarField constant(mesh.num_local(), 1e-5);
  const auto rc =
      flow::stability_rates(mesh, a.laplacian_weights(), constant, initial.velocity, scratch);
  const auto rs =
      flow::stability_rates(mesh, a.laplacian_weights(), 1e-5, initial.velocity, scratch);
  CHECK(rc.stability == doctest::Approx(rs.stability).epsilon(1e-14));
  CHECK(rc.viscous == doctest::Approx(rs.viscous).epsilon(1e-14));

  const double dt = 0.02;
  auto sa = initial, sb = initial, sc = initial;
  for (int s = 0; s < 3; ++s) a.step(sa, dt), b.step(sb, dt), c.step(sc, dt);
  double same = 0, newtonian_diff = 0, change = 0;
  for (int i = 0; i < mesh.num_owned; ++i) {
    same = std::max(same, (sa.velocity[i] - sb.velocity[i]).norm());
    newtonian_diff = std::max(newtonian_diff, (sa.velocity[i] - sc.velocity[i]).norm());
    change = std::max(change, (sa.velocity[i] - initial.velocity[i]).norm());
  }
  same = mesh.comm.max(same), newtonian_diff = mesh.comm.max(newtonian_diff);
  change = mesh.comm.max(change);
  MESSAGE("Carreau-Yasuda vs the per-stage hook: " << same << ", vs Newtonian mu_0: "
                                                   << newtonian_diff << ", change " << change);
  CHECK(same <= 1e-14 * U);
  CHECK(newtonian_diff > 0.1 * change);
}

TEST_CASE(
    "Carreau-Yasuda with an LES model: the solver's viscosity is mu(gamma_dot) / rho + nu_sgs") {
  // The same box and vortex as above with Smagorinsky's model (les::SubgridViscosity, updated
  // every RK stage, as [les] model = "smagorinsky", update = "stage" wires it): the run must
  // equal, to round-off, a run without the model whose hook supplies the sum itself, and differ
  // from the Carreau-Yasuda run without LES; the nodal viscosity the time step sees is the sum.
  const VortexBox vb;
  const auto& mesh = vb.mesh;
  const auto& initial = vb.initial;
  const double rho = VortexBox::rho, U = VortexBox::U;
  std::vector<double> delta;
  for (int i = 0; i < mesh.num_local(); ++i) delta.push_back(std::cbrt(mesh.volume[i]));
  const les::SubgridViscosity smagorinsky(les::SgsKind::smagorinsky, std::nullopt, delta);
  const auto cy = cho_kensey();
  flow::ProjectionOptions base;
  base.density = rho;
  base.poisson.tolerance = 1e-12;
  auto les_cy = base;
  les_cy.rheology = cy;
  les_cy.subgrid_viscosity = [&](int stage, const flow::TensorField& grad, flow::ScalarField& nu) {
    smagorinsky(stage, grad, nu);
  };
  auto sum = base;  // no law: the hook gives mu(gamma_dot) / rho + nu_sgs
  sum.subgrid_viscosity = [&](int stage, const flow::TensorField& grad, flow::ScalarField& nu) {
    smagorinsky(stage, grad, nu);
    for (std::size_t i = 0; i < grad.size(); ++i)
      nu[i] += flow::apparent_viscosity(cy, flow::shear_rate(grad[i])) / rho;
  };
  auto cy_only = base;
  cy_only.rheology = cy;
  flow::ProjectionRK4 a(mesh, les_cy), b(mesh, sum), c(mesh, cy_only);
  const double dt = 0.02;
  auto sa = initial, sb = initial, sc = initial;
  for (int s = 0; s < 3; ++s) a.step(sa, dt), b.step(sb, dt), c.step(sc, dt);
  double same = 0, les_effect = 0, sgs_max = 0;
  for (int i = 0; i < mesh.num_owned; ++i) {
    same = std::max(same, (sa.velocity[i] - sb.velocity[i]).norm());
    les_effect = std::max(les_effect, (sa.velocity[i] - sc.velocity[i]).norm());
    sgs_max = std::max(sgs_max, a.subgrid_viscosity()[i]);
  }
  same = mesh.comm.max(same), les_effect = mesh.comm.max(les_effect);
  MESSAGE("LES + Carreau-Yasuda vs the summing hook: " << same << ", vs Carreau-Yasuda alone: "
                                                       << les_effect << ", max nu_sgs "
                                                       << mesh.comm.max(sgs_max));
  CHECK(mesh.comm.max(sgs_max) > 0);
  CHECK(same <= 1e-14 * U);
  CHECK(les_effect > 1e3 * std::max(same, 1e-18));
  // The nodal viscosity of the time step's bound: mu(gamma_dot(u)) / rho + the last nu_sgs.
  const auto nu_sgs = a.subgrid_viscosity();
  const auto& field = a.viscosity_field(sa.velocity);
  flow::TensorField grad;
  flow::gradient(mesh, sa.velocity, grad);
  double worst = 0;
  for (int i = 0; i < mesh.num_owned; ++i)
    worst = std::max(
        worst, std::abs(field[i] - (flow::apparent_viscosity(cy, flow::shear_rate(grad[i])) / rho +
                                    nu_sgs[i])));
  CHECK(mesh.comm.max(worst) == 0.0);
}
