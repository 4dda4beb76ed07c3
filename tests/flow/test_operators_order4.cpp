// 4th-order gradient, divergence and viscous operators (flow/operators_order4.hpp) on a smooth,
// fully 3D periodic field against the exact point values, on periodic unit boxes of 8, 16, 32
// cells per side (orders from the two finest):
//   uniform hexahedra and Kuhn-split tetrahedra: observed L2 and max orders >= 3.5 for all
//     three (symmetric node stars), and below the 2nd-order operators' errors;
//     Measured L2 orders: hexa 3.98 (grad), 3.98 (div), 3.97 (viscous); split tetra 3.85, 3.93,
//     3.93 (2nd-order operators 1.95-1.99); n 32 errors 24x (tetra grad) to 130x (hexa grad) lower;
//   tetrahedra perturbed by 20% of h: first order for grad and div, an O(1) viscous error as
//     the 2nd-order operator's (the point truncation error of edge operators on irregular
//     meshes converges slowly, Diskin & Thomas, NASA 2011); bounds from the measured values;
// plus np = N against one rank (the edge corrections use the first ghost layer's gradients)
// and the refusals (fewer than 2 ghost layers, an LES model).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/operators_order4.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"

using namespace valsalva;
using flow::ScalarField;
using flow::TensorField;
using flow::VectorField;

namespace {

constexpr double k = 2 * std::numbers::pi;

double phi_exact(const Eigen::Vector3d& x) {  // lap phi = -3 k^2 phi
  return std::sin(k * x.x()) * std::cos(k * x.y()) * std::sin(k * x.z());
}
Eigen::Vector3d grad_phi_exact(const Eigen::Vector3d& x) {
  const double X = k * x.x(), Y = k * x.y(), Z = k * x.z();
  return k * Eigen::Vector3d(std::cos(X) * std::cos(Y) * std::sin(Z),
                             -std::sin(X) * std::sin(Y) * std::sin(Z),
                             std::sin(X) * std::cos(Y) * std::cos(Z));
}
Eigen::Vector3d u_exact(const Eigen::Vector3d& x) {
  const double X = k * x.x(), Y = k * x.y(), Z = k * x.z();
  return {std::sin(X) * std::cos(Y) + 0.5 * std::cos(Z),
          std::cos(X) * std::sin(Z) + 0.3 * std::sin(Y),
          std::sin(Y) * std::cos(Z) + 0.4 * std::cos(X)};
}
double div_u_exact(const Eigen::Vector3d& x) {
  const double X = k * x.x(), Y = k * x.y(), Z = k * x.z();
  return k * (std::cos(X) * std::cos(Y) + 0.3 * std::cos(Y) - std::sin(Y) * std::sin(Z));
}
Eigen::Vector3d lap_u_exact(const Eigen::Vector3d& x) {
  const double X = k * x.x(), Y = k * x.y(), Z = k * x.z();
  return -k * k *
         Eigen::Vector3d(2 * std::sin(X) * std::cos(Y) + 0.5 * std::cos(Z),
                         2 * std::cos(X) * std::sin(Z) + 0.3 * std::sin(Y),
                         2 * std::sin(Y) * std::cos(Z) + 0.4 * std::cos(X));
}

// Max and volume-weighted L2 errors over owned nodes.
struct Norms {
  double max = 0, l2 = 0;
};
struct Errors {
  double h = 0;
  Norms grad, div, visc;
};

struct Fields {
  VectorField grad, visc;
  ScalarField div;
};

struct Built {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
};

Built build(const test::MeshKind& kind, int n, MPI_Comm comm = MPI_COMM_WORLD) {
  Built m;
  m.mesh = mesh::generate_box(test::periodic_box(kind.type, n, kind.perturbation));
  m.metrics = mesh::compute_dual_metrics(m.mesh);
  m.local = mesh::distribute(m.mesh, m.metrics, comm, {2, mesh::PartitionMethod::metis});
  return m;
}

// The operators on the exact fields; order4 = false: the 2nd-order operators of
// flow/operators.hpp (viscous term with the same Poisson weights, no correction).
Fields apply(const Built& m, bool order4) {
  const auto& local = m.local;
  const int n = local.num_local();
  ScalarField phi(n);
  VectorField u(n);
  for (int i = 0; i < n; ++i) {
    phi[i] = phi_exact(local.position[i]);
    u[i] = u_exact(local.position[i]);
  }
  const auto weights = flow::poisson_weights(m.mesh, m.metrics, local);
  TensorField grad_u;
  flow::gradient(local, u, grad_u);
  Fields f;
  if (order4) {
    flow::Order4Operators ops(local, weights);
    ops.gradient(phi, f.grad);
    ops.divergence(u, f.div);
    ops.viscous(1.0, u, grad_u, f.visc);
  } else {
    flow::gradient(local, phi, f.grad);
    flow::divergence(local, u, f.div);
    flow::viscous(local, weights, 1.0, u, grad_u, f.visc, false);
  }
  return f;
}

Errors measure(const Built& m, bool order4, int n) {
  const auto& local = m.local;
  const Fields f = apply(m, order4);
  Errors e;
  e.h = 1.0 / n;
  double volume = 0;
  auto add = [&](Norms& norms, double err, double v) {
    norms.max = std::max(norms.max, err);
    norms.l2 += v * err * err;
  };
  for (int i = 0; i < local.num_owned; ++i) {
    const auto& x = local.position[i];
    const double v = local.volume[i];
    add(e.grad, (f.grad[i] - grad_phi_exact(x)).norm(), v);
    add(e.div, std::abs(f.div[i] - div_u_exact(x)), v);
    add(e.visc, (f.visc[i] - lap_u_exact(x)).norm(), v);
    volume += v;
  }
  volume = local.comm.sum(volume);
  for (Norms* p : {&e.grad, &e.div, &e.visc}) {
    p->max = local.comm.max(p->max);
    p->l2 = std::sqrt(local.comm.sum(p->l2) / volume);
  }
  return e;
}

double order(const Errors& a, const Errors& b, Norms Errors::*term, bool l2) {
  const Norms &na = a.*term, &nb = b.*term;
  return test::observed_order(l2 ? na.l2 : na.max, l2 ? nb.l2 : nb.max, a.h, b.h);
}

}  // namespace

TEST_CASE("4th-order operators: observed orders on a smooth periodic field") {
  for (const auto& kind : test::order_mesh_kinds()) {
    CAPTURE(kind.type);
    CAPTURE(kind.perturbation);
    std::vector<Errors> e2, e4;
    for (int n : {8, 16, 32}) {
      const Built m = build(kind, n);
      e2.push_back(measure(m, false, n));
      e4.push_back(measure(m, true, n));
      MESSAGE(kind.type << " pert " << kind.perturbation << " n " << n << " L2 (2nd | 4th): grad "
                        << e2.back().grad.l2 << " | " << e4.back().grad.l2 << ", div "
                        << e2.back().div.l2 << " | " << e4.back().div.l2 << ", viscous "
                        << e2.back().visc.l2 << " | " << e4.back().visc.l2);
    }
    const auto &a = e4[1], &b = e4[2];
    MESSAGE(kind.type << " pert " << kind.perturbation << " orders (L2, max): grad "
                      << order(a, b, &Errors::grad, true) << ", "
                      << order(a, b, &Errors::grad, false) << "; div "
                      << order(a, b, &Errors::div, true) << ", " << order(a, b, &Errors::div, false)
                      << "; viscous " << order(a, b, &Errors::visc, true) << ", "
                      << order(a, b, &Errors::visc, false)
                      << " (2nd-order operators: " << order(e2[1], e2[2], &Errors::grad, true)
                      << ", " << order(e2[1], e2[2], &Errors::div, true) << ", "
                      << order(e2[1], e2[2], &Errors::visc, true) << ")");
    if (kind.asserted) {
      for (auto term : {&Errors::grad, &Errors::div, &Errors::visc}) {
        CHECK(order(a, b, term, true) >= 3.5);
        CHECK(order(a, b, term, false) >= 3.5);
        CHECK((b.*term).l2 < 0.1 * (e2[2].*term).l2);
      }
    } else {
      // Measured (L2, n 16 -> 32): grad 1.06 (2nd-order operator 1.31), div 1.03 (1.24), both
      // below the 2nd-order errors at n 32 (0.139 vs 0.186, 0.132 vs 0.172); the viscous error
      // is O(1) for both (9.86 vs 9.73: the pointwise truncation error of the P1 Laplacian on
      // perturbed tetrahedra does not converge; the solution error does).
      CHECK(order(a, b, &Errors::grad, true) >= 0.9);
      CHECK(order(a, b, &Errors::div, true) >= 0.9);
      CHECK(b.grad.l2 < e2[2].grad.l2);
      CHECK(b.div.l2 < e2[2].div.l2);
      CHECK(b.visc.l2 < 1.05 * e2[2].visc.l2);
    }
  }
}

TEST_CASE("4th-order operators: np = N reproduces one rank") {
  const test::MeshKind kind{"tetra", 0.2, false};
  const Built m = build(kind, 8);
  const Built serial = build(kind, 8, MPI_COMM_SELF);
  const Fields f = apply(m, true), s = apply(serial, true);
  auto by_node = [](const mesh::LocalMesh& local, const std::vector<double>& values, int c) {
    return test::gather_by_dual_node(local, values, c, local.global_nodes);
  };
  CHECK(test::max_abs_difference(by_node(m.local, test::flatten(f.grad), 3),
                                 by_node(serial.local, test::flatten(s.grad), 3)) < 1e-9);
  CHECK(test::max_abs_difference(by_node(m.local, f.div, 1), by_node(serial.local, s.div, 1)) <
        1e-9);
  CHECK(test::max_abs_difference(by_node(m.local, test::flatten(f.visc), 3),
                                 by_node(serial.local, test::flatten(s.visc), 3)) < 1e-9);
}

TEST_CASE("4th-order operators: refused with one ghost layer and with a non-Newtonian fluid") {
  const auto mesh = mesh::generate_box(test::periodic_box("hexa", 6));
  const auto metrics = mesh::compute_dual_metrics(mesh);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1) {
    const auto thin =
        mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {1, mesh::PartitionMethod::metis});
    CHECK_THROWS_WITH_AS(flow::Order4Operators(thin, flow::laplacian_weights(thin)),
                         doctest::Contains("at least 2 ghost layers"), std::invalid_argument);
  }
  const auto local =
      mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  flow::ProjectionOptions options;
  options.fourth_order_operators = true;
  options.rheology.law = flow::ViscosityLaw::carreau_yasuda;  // Cho & Kensey's blood
  options.rheology.mu_0 = 0.056, options.rheology.mu_inf = 0.00345;
  options.rheology.lambda = 3.313, options.rheology.a = 2, options.rheology.n = 0.3568;
  CHECK_THROWS_WITH_AS(flow::ProjectionRK4(local, options),
                       doctest::Contains("no variable-viscosity (non-Newtonian) viscous term"),
                       std::invalid_argument);
}

// With a subgrid model the molecular term takes the 4th-order operator and the subgrid term the
// 2nd-order full-stress one. A constant nu_sgs = nu_s on the 2D Taylor-Green vortex (period 2 pi,
// U0 = 1) must then decay the kinetic energy as exp(-4 (nu + nu_s) t): without the subgrid term
// it would decay with nu alone (a rate 3 times too small here). The 2nd-order full-stress term
// misses the rate by about (k h)^2 / 12 = 1.3 % of nu_s at 16 cells per period (measured in the
// test's message), so 3 %.
TEST_CASE("4th-order operators with a subgrid model: the subgrid viscosity decays the vortex") {
  auto slab = test::periodic_box("hexa", 16);  // [0, 2 pi]^2 x 3 cells
  slab.cells = {16, 16, 3};
  slab.length = {2 * std::numbers::pi, 2 * std::numbers::pi, 3 * 2 * std::numbers::pi / 16};
  const auto mesh = mesh::generate_box(slab);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local =
      mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  const double nu = 0.01, nu_s = 0.02, t_end = 2.0, dt = 0.01;
  flow::ProjectionOptions options;
  options.viscosity = nu;
  options.scheme = flow::ConvectionKind::central4;
  options.fourth_order_operators = true;
  options.poisson.tolerance = 1e-12;
  options.subgrid_viscosity = [&](int, const TensorField& grad, ScalarField& nu_sgs) {
    nu_sgs.assign(grad.size(), nu_s);
  };
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));
  flow::FlowState state;
  for (int i = 0; i < local.num_local(); ++i) {
    const auto& x = local.position[i];
    state.velocity.emplace_back(std::sin(x.x()) * std::cos(x.y()),
                                -std::cos(x.x()) * std::sin(x.y()), 0.0);
    state.pressure.push_back(0.25 * (std::cos(2 * x.x()) + std::cos(2 * x.y())));
  }
  const double e0 = flow::kinetic_energy(local, 1.0, state.velocity);
  for (int s = 0; s < static_cast<int>(std::lround(t_end / dt)); ++s) solver.step(state, dt);
  const double rate = -std::log(flow::kinetic_energy(local, 1.0, state.velocity) / e0) /
                      (4 * state.time);  // the effective nu + nu_s
  MESSAGE("effective viscosity " << rate << " against nu + nu_s = " << nu + nu_s
                                 << "; subgrid part off by " << (rate - nu) / nu_s - 1);
  CHECK(std::abs((rate - nu) / nu_s - 1) < 0.03);
}
