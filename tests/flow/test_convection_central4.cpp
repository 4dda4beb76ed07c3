// Convection operators on a smooth, fully 3D periodic velocity field against the exact
// div(u u) at the nodes (point values), on 3D periodic boxes of 8, 16, 32 cells per side:
//   central4 (edge form): observed order >= 3.5 (max and L2) on uniform hexahedra and
//     Kuhn-split tetrahedra (symmetric node stars: all O(h^2) terms cancel, see the header);
//     perturbed tetrahedra (20% of h) reported, first order asserted (truncation error);
//   central2: order 2 (>= 1.9) on the uniform meshes, the reference the 4th-order scheme beats;
//   central4 deconvolution form (architecture text taken literally): order ~2 on the uniform
//     meshes (asserted to stay below 3, the reason the edge form is the scene's central4);
// plus the refusal of fewer than 2 ghost layers (np 2) and np = 1 vs np = 2 agreement.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/convection_central4.hpp"

using namespace valsalva;
using flow::VectorField;

namespace {

constexpr double k = 2 * std::numbers::pi;

Eigen::Vector3d u_exact(const Eigen::Vector3d& x) {
  const double X = k * x.x(), Y = k * x.y(), Z = k * x.z();
  return {std::sin(X) * std::cos(Y) + 0.5 * std::cos(Z),
          std::cos(X) * std::sin(Z) + 0.3 * std::sin(Y),
          std::sin(Y) * std::cos(Z) + 0.4 * std::cos(X)};
}

Eigen::Matrix3d grad_u_exact(const Eigen::Vector3d& x) {  // (i, j) = d u_i / d x_j
  const double X = k * x.x(), Y = k * x.y(), Z = k * x.z();
  Eigen::Matrix3d g;
  g << std::cos(X) * std::cos(Y), -std::sin(X) * std::sin(Y), -0.5 * std::sin(Z),
      -std::sin(X) * std::sin(Z), 0.3 * std::cos(Y), std::cos(X) * std::cos(Z), -0.4 * std::sin(X),
      std::cos(Y) * std::cos(Z), -std::sin(Y) * std::sin(Z);
  return k * g;
}

// div(u u)_i = (div u) u_i + (u . grad) u_i
Eigen::Vector3d conv_exact(const Eigen::Vector3d& x) {
  const Eigen::Vector3d u = u_exact(x);
  const Eigen::Matrix3d g = grad_u_exact(x);
  return g.trace() * u + g * u;
}

struct Errors {
  double h, max, l2;
};

struct Built {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
};

Built build(const test::MeshKind& kind, int n, int ghost_layers = 2) {
  Built m;
  m.mesh = mesh::generate_box(test::periodic_box(kind.type, n, kind.perturbation));
  m.metrics = mesh::compute_dual_metrics(m.mesh);
  m.local = mesh::distribute(m.mesh, m.metrics, MPI_COMM_WORLD,
                             {ghost_layers, mesh::PartitionMethod::metis});
  return m;
}

Errors measure(const mesh::LocalMesh& local, flow::ConvectionScheme& scheme, int n,
               VectorField* result = nullptr) {
  VectorField u(local.num_local()), conv;
  for (int i = 0; i < local.num_local(); ++i) u[i] = u_exact(local.position[i]);
  scheme.apply(u, conv);
  double emax = 0, e2 = 0, vol = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    const double e = (conv[i] - conv_exact(local.position[i])).norm();
    emax = std::max(emax, e);
    e2 += local.volume[i] * e * e;
    vol += local.volume[i];
  }
  if (result) *result = conv;
  return {1.0 / n, local.comm.max(emax), std::sqrt(local.comm.sum(e2) / local.comm.sum(vol))};
}

}  // namespace

TEST_CASE("convection schemes: observed orders on a smooth periodic field") {
  using Form = flow::ConvectionCentral4::Form;
  for (const auto& kind : test::order_mesh_kinds()) {
    CAPTURE(kind.type);
    CAPTURE(kind.perturbation);
    std::vector<Errors> c2, c4, cd;
    for (int n : {8, 16, 32}) {
      const Built m = build(kind, n);
      auto central2 = flow::make_convection_scheme(flow::ConvectionKind::central2, m.local);
      flow::ConvectionCentral4 central4(m.local), deconv(m.local, Form::deconvolution);
      c2.push_back(measure(m.local, *central2, n));
      c4.push_back(measure(m.local, central4, n));
      cd.push_back(measure(m.local, deconv, n));
      MESSAGE(kind.type << " pert " << kind.perturbation << " n " << n << ": central2 max "
                        << c2.back().max << " L2 " << c2.back().l2 << " | central4 max "
                        << c4.back().max << " L2 " << c4.back().l2 << " | deconvolution max "
                        << cd.back().max << " L2 " << cd.back().l2);
    }
    auto order = [](const std::vector<Errors>& e, bool l2) {
      return l2 ? test::observed_order(e[1].l2, e[2].l2, e[1].h, e[2].h)
                : test::observed_order(e[1].max, e[2].max, e[1].h, e[2].h);
    };
    MESSAGE("orders (max, L2): central2 "
            << order(c2, false) << ", " << order(c2, true) << "; central4 " << order(c4, false)
            << ", " << order(c4, true) << "; deconvolution " << order(cd, false) << ", "
            << order(cd, true));
    if (kind.asserted) {
      CHECK(order(c4, false) >= 3.5);
      CHECK(order(c4, true) >= 3.5);
      CHECK(order(c2, false) >= 1.9);
      CHECK(order(c2, true) >= 1.9);
      CHECK(order(cd, true) < 3.0);  // measured 1.95 hexa, 2.36 (pre-asymptotic) tetra
      CHECK(c4[2].l2 < 0.05 * c2[2].l2);
    } else {
      // Point truncation errors of edge schemes on irregular meshes converge slowly (Diskin &
      // Thomas, "Notes on accuracy of finite-volume discretization schemes on irregular grids",
      // NASA 2011): measured L2 orders 1.0 (central4) and 1.3 (central2) from 16 to 32; the
      // solution error converges faster (Taylor-Green case). Asserted: first order, and central4
      // below central2 on the finest level.
      CHECK(order(c4, true) >= 0.9);
      CHECK(c4[2].l2 < c2[2].l2);
    }
  }
}

TEST_CASE("central4: np = N reproduces one rank; fewer than 2 ghost layers are refused") {
  const test::MeshKind kind{"tetra", 0.2, false};
  const Built m = build(kind, 8);
  flow::ConvectionCentral4 scheme(m.local);
  VectorField conv;
  measure(m.local, scheme, 8, &conv);
  const auto all = test::gather_by_dual_node(
      m.local, std::vector<double>(conv.data()->data(), conv.data()->data() + 3 * conv.size()), 3,
      m.local.global_nodes);
  // Serial reference on every rank.
  const auto mesh = mesh::generate_box(test::periodic_box(kind.type, 8, kind.perturbation));
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto serial =
      mesh::distribute(mesh, metrics, MPI_COMM_SELF, {2, mesh::PartitionMethod::metis});
  flow::ConvectionCentral4 serial_scheme(serial);
  VectorField serial_conv;
  measure(serial, serial_scheme, 8, &serial_conv);
  std::vector<double> ref(3 * serial.global_nodes);
  for (int i = 0; i < serial.num_owned; ++i)
    for (int c = 0; c < 3; ++c) ref[3 * serial.dual_node[i] + c] = serial_conv[i][c];
  CHECK(test::max_abs_difference(all, ref) < 1e-9);

  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1) {
    const Built thin = build(kind, 8, 1);
    CHECK_THROWS_WITH_AS(flow::ConvectionCentral4(thin.local),
                         doctest::Contains("at least 2 ghost layers"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(flow::parse_convection_kind("central6"),
                         doctest::Contains("'central6' is not one of central2, central4"),
                         std::invalid_argument);
  }
}
