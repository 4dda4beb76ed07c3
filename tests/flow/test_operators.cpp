// Edge-based operators: exact for linear fields on perturbed/mixed meshes, second-order for a
// smooth periodic field on uniform hexahedra and split tetrahedra (observed order >= 1.9 from
// the two finest of three levels; 1.8 for the Laplacian on split tetrahedra, still
// pre-asymptotic; perturbed tetrahedra are reported), and np = N reproduces the
// single-rank numbers to 1e-12.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/operators.hpp"
#include "flow/poisson_weights.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/periodic_pipe_generator.hpp"

using namespace valsalva;
using flow::ScalarField;
using flow::TensorField;
using flow::VectorField;

namespace {

constexpr double k = 2 * std::numbers::pi;

double phi_exact(const Eigen::Vector3d& x) {
  return std::sin(k * x.x()) * std::cos(k * x.y()) * std::sin(k * x.z());
}
Eigen::Vector3d grad_phi_exact(const Eigen::Vector3d& x) {
  const double sx = std::sin(k * x.x()), cx = std::cos(k * x.x());
  const double sy = std::sin(k * x.y()), cy = std::cos(k * x.y());
  const double sz = std::sin(k * x.z()), cz = std::cos(k * x.z());
  return k * Eigen::Vector3d(cx * cy * sz, -sx * sy * sz, sx * cy * cz);
}
Eigen::Vector3d u_exact(const Eigen::Vector3d& x) {
  return {std::sin(k * x.x()) * std::cos(k * x.y()), std::cos(k * x.x()) * std::sin(k * x.z()),
          std::sin(k * x.y()) * std::cos(k * x.z())};
}
Eigen::Matrix3d grad_u_exact(const Eigen::Vector3d& x) {
  const double sx = std::sin(k * x.x()), cx = std::cos(k * x.x());
  const double sy = std::sin(k * x.y()), cy = std::cos(k * x.y());
  const double sz = std::sin(k * x.z()), cz = std::cos(k * x.z());
  Eigen::Matrix3d g;
  g << cx * cy, -sx * sy, 0, -sx * sz, 0, cx * cz, 0, cy * cz, -sy * sz;
  return k * g;
}

struct Errors {
  double grad = 0, div = 0, lap = 0, conv = 0, visc = 0;
};

// Volume-weighted L2 errors of every operator at owned nodes.
Errors operator_errors(const mesh::LocalMesh& mesh) {
  const int n = mesh.num_local();
  ScalarField phi(n), div, lap;
  VectorField u(n), grad, conv, visc;
  TensorField grad_u;
  for (int i = 0; i < n; ++i) {
    phi[i] = phi_exact(mesh.position[i]);
    u[i] = u_exact(mesh.position[i]);
  }
  const auto weights = flow::laplacian_weights(mesh);
  flow::gradient(mesh, phi, grad);
  flow::gradient(mesh, u, grad_u);
  flow::divergence(mesh, u, div);
  flow::laplacian(mesh, weights, phi, grad, lap);
  flow::convection(mesh, u, u, conv);
  flow::viscous(mesh, weights, 0.5, u, grad_u, visc);
  Errors e;
  for (int i = 0; i < mesh.num_owned; ++i) {
    const auto& x = mesh.position[i];
    const double v = mesh.volume[i];
    const Eigen::Matrix3d gu = grad_u_exact(x);
    const Eigen::Vector3d ue = u_exact(x);
    e.grad += v * (grad[i] - grad_phi_exact(x)).squaredNorm();
    e.div += v * std::pow(div[i] - gu.trace(), 2);
    e.lap += v * std::pow(lap[i] + 3 * k * k * phi_exact(x), 2);
    e.conv += v * (conv[i] - (gu * ue + ue * gu.trace())).squaredNorm();
    e.visc += v * (visc[i] + 0.5 * 2 * k * k * ue).squaredNorm();
  }
  for (double* p : {&e.grad, &e.div, &e.lap, &e.conv, &e.visc}) *p = std::sqrt(mesh.comm.sum(*p));
  return e;
}

using test::local_box;

}  // namespace

TEST_CASE("operators are exact for linear fields") {
  for (std::string type : {"tetra", "hexa", "mixed"}) {
    CAPTURE(type);
    mesh::BoxSpec spec;
    spec.cell_type = mesh::parse_box_cell_type(type);
    spec.cells = {5, 4, 6};
    spec.length = Eigen::Vector3d(1.0, 0.8, 1.2);
    spec.perturbation = 0.2;
    const auto mesh = local_box(spec, MPI_COMM_WORLD);
    const int n = mesh.num_local();
    const Eigen::Vector3d g(0.7, -1.3, 2.1);
    Eigen::Matrix3d A;
    A << 0.3, -1.2, 0.5, 2.0, -0.4, 0.9, -0.6, 1.1, 0.1;
    const Eigen::Vector3d u0(0.4, -0.9, 1.5);
    ScalarField phi(n), div, lap;
    VectorField u(n), v(n), uc(n, u0), grad, conv, visc;
    TensorField grad_v;
    for (int i = 0; i < n; ++i) {
      phi[i] = 1.5 + g.dot(mesh.position[i]);
      v[i] = A * mesh.position[i];
    }
    const auto weights = flow::laplacian_weights(mesh);
    flow::gradient(mesh, phi, grad);
    flow::gradient(mesh, v, grad_v);
    flow::divergence(mesh, v, div);
    flow::laplacian(mesh, weights, phi, grad, lap);
    flow::convection(mesh, uc, v, conv);
    flow::viscous(mesh, weights, 1.0, v, grad_v, visc);
    std::vector<char> on_boundary(n, 0);
    for (const auto& b : mesh.boundary) on_boundary[b.node] = 1;
    std::int64_t exact_nodes = 0;
    double e_grad = 0, e_gradv = 0, e_lap = 0, e_visc = 0, e_div = 0, e_conv = 0;
    for (int i = 0; i < n; ++i) {  // ghosts too: the halo insert must have filled them
      const double hi = mesh.h[i];
      e_grad = std::max(e_grad, (grad[i] - g).norm() / g.norm());
      e_gradv = std::max(e_gradv, (grad_v[i] - A).norm() / A.norm());
      // Laplacian of a linear field vanishes; scale: |g| / h.
      e_lap = std::max(e_lap, std::abs(lap[i]) * hi / g.norm());
      e_visc = std::max(e_visc, visc[i].norm() * hi / A.norm());
      // Divergence and convection carry no correction matrix: exact where M_j = I (interior
      // nodes of simplicial meshes; perturbed hexahedra have M_j != I).
      if (!on_boundary[i] &&
          (mesh.gradient_correction[i] - Eigen::Matrix3d::Identity()).norm() < 1e-12) {
        ++exact_nodes;
        e_div = std::max(e_div, std::abs(div[i] - A.trace()) / A.norm());
        e_conv = std::max(e_conv, (conv[i] - A * u0).norm() / (A.norm() * u0.norm()));
      }
    }
    const auto& comm = mesh.comm;
    CHECK(comm.max(e_grad) < 1e-12);
    CHECK(comm.max(e_gradv) < 1e-12);
    CHECK(comm.max(e_lap) < 1e-11);
    CHECK(comm.max(e_visc) < 1e-11);
    CHECK(comm.max(e_div) < 1e-12);
    CHECK(comm.max(e_conv) < 1e-12);
    if (type == "tetra") CHECK(comm.sum(exact_nodes) > 0);
  }
}

TEST_CASE("operators converge at second order on periodic boxes") {
  for (const auto& level : test::order_mesh_kinds()) {
    CAPTURE(level.type);
    CAPTURE(level.perturbation);
    std::vector<Errors> errors;
    const std::vector<int> ns = {8, 16, 32};
    for (int n : ns)
      errors.push_back(operator_errors(
          local_box(test::periodic_box(level.type, n, level.perturbation), MPI_COMM_WORLD)));
    auto order = [&](double Errors::*field) {
      return test::observed_order(errors[1].*field, errors[2].*field, 1.0 / ns[1], 1.0 / ns[2]);
    };
    const double o_grad = order(&Errors::grad), o_div = order(&Errors::div),
                 o_lap = order(&Errors::lap), o_conv = order(&Errors::conv),
                 o_visc = order(&Errors::visc);
    MESSAGE(level.type << " perturbation " << level.perturbation << ": orders grad " << o_grad
                       << " div " << o_div << " lap " << o_lap << " conv " << o_conv << " visc "
                       << o_visc << "; finest errors grad " << errors[2].grad << " lap "
                       << errors[2].lap << " conv " << errors[2].conv);
    if (level.asserted) {
      CHECK(o_grad >= 1.9);
      CHECK(o_div >= 1.9);
      CHECK(o_conv >= 1.9);
      // On split tetrahedra the corrected Laplacian is still pre-asymptotic at these sizes:
      // measured orders 1.73 (12 -> 24) and 1.85 (16 -> 32), rising towards 2.
      const double lap_order = level.type == "hexa" ? 1.9 : 1.8;
      CHECK(o_lap >= lap_order);
      CHECK(o_visc >= lap_order);
    }
  }
}

TEST_CASE("operators at np ranks reproduce one rank") {
  const auto spec = test::periodic_box("tetra", 6, 0.2);
  const auto par = local_box(spec, MPI_COMM_WORLD);
  const auto ser = local_box(spec, MPI_COMM_SELF);
  const auto nodes = par.comm.sum(static_cast<std::int64_t>(par.num_owned));
  auto run = [&](const mesh::LocalMesh& mesh) {
    const int n = mesh.num_local();
    ScalarField phi(n), div, lap;
    VectorField u(n), grad, conv, visc;
    TensorField grad_u;
    for (int i = 0; i < n; ++i) {
      phi[i] = phi_exact(mesh.position[i]);
      u[i] = u_exact(mesh.position[i]);
    }
    const auto weights = flow::laplacian_weights(mesh);
    flow::gradient(mesh, phi, grad);
    flow::gradient(mesh, u, grad_u);
    flow::divergence(mesh, u, div);
    flow::laplacian(mesh, weights, phi, grad, lap);
    flow::convection(mesh, u, u, conv);
    flow::viscous(mesh, weights, 1.0, u, grad_u, visc);
    std::vector<double> all;
    for (int i = 0; i < n; ++i) {
      all.insert(all.end(), grad[i].data(), grad[i].data() + 3);
      all.insert(all.end(), conv[i].data(), conv[i].data() + 3);
      all.insert(all.end(), visc[i].data(), visc[i].data() + 3);
      all.push_back(div[i]);
      all.push_back(lap[i]);
    }
    return test::gather_by_dual_node(mesh, all, 11, nodes);
  };
  const auto a = run(par);
  const auto b = run(ser);
  double scale = 0;
  for (double x : b) scale = std::max(scale, std::abs(x));
  CHECK(test::max_abs_difference(a, b) / scale < 1e-12);
}

TEST_CASE("viscous with the P1 stiffness weights and no correction is exact for linear fields") {
  // ProjectionOptions::stiffness_viscous: the two-point flux with the Poisson matrix's P1
  // weights is the median-dual flux of the piecewise-linear field, so a linear field has zero
  // Laplacian at every node of a perturbed tetrahedral mesh, boundary nodes included (their
  // boundary-face flux grad v . A closes the dual volume).
  mesh::BoxSpec spec;
  spec.cell_type = mesh::BoxCellType::tetra;
  spec.cells = {5, 4, 6};
  spec.length = Eigen::Vector3d(1.0, 0.8, 0.3);  // flat cells, as in the DFG slab
  spec.perturbation = 0.2;
  const auto box = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(box);
  const auto mesh =
      mesh::distribute(box, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  const auto p1 = flow::poisson_weights(box, metrics, mesh);
  Eigen::Matrix3d A;
  A << 0.3, -1.2, 0.5, 2.0, -0.4, 0.9, -0.6, 1.1, 0.1;
  VectorField v(mesh.num_local()), visc;
  TensorField grad_v;
  for (int i = 0; i < mesh.num_local(); ++i) v[i] = A * mesh.position[i];
  flow::gradient(mesh, v, grad_v);
  flow::viscous(mesh, p1, 1.0, v, grad_v, visc, false);
  double e = 0;
  for (int i = 0; i < mesh.num_local(); ++i) e = std::max(e, visc[i].norm() * mesh.h[i] / A.norm());
  CHECK(mesh.comm.max(e) < 1e-11);
  // Without the correction the two-point weights are not exact there: the test can fail.
  flow::viscous(mesh, flow::laplacian_weights(mesh), 1.0, v, grad_v, visc, false);
  double e2 = 0;
  for (int i = 0; i < mesh.num_owned; ++i) e2 = std::max(e2, visc[i].norm() * mesh.h[i] / A.norm());
  CHECK(mesh.comm.max(e2) > 1e-3);
}

TEST_CASE("viscous with the slab stiffness weights of prisms is exact for linear fields") {
  // flow::slab_stiffness_weights on the right prisms of an extruded disk (the cylinder slab's
  // cells unsplit): the lumped tensor-product weights close the dual volumes like the P1 ones,
  // so a linear field has zero Laplacian at every node, boundary nodes included.
  mesh::PeriodicPipeSpec spec;
  spec.radius = 0.5, spec.target_size = 0.15, spec.layers = 3, spec.length = 0.2;
  auto pipe = mesh::generate_periodic_pipe_mesh(spec);
  pipe.periodic.clear();  // zmin / zmax as plain boundaries: a linear field is not periodic
  const auto metrics = mesh::compute_dual_metrics(pipe);
  const auto mesh =
      mesh::distribute(pipe, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  Eigen::Matrix3d A;
  A << 0.3, -1.2, 0.5, 2.0, -0.4, 0.9, -0.6, 1.1, 0.1;
  VectorField v(mesh.num_local()), visc;
  TensorField grad_v;
  for (int i = 0; i < mesh.num_local(); ++i) v[i] = A * mesh.position[i];
  flow::gradient(mesh, v, grad_v);
  const auto error = [&](const std::vector<double>& w) {
    flow::viscous(mesh, w, 1.0, v, grad_v, visc, false);
    double e = 0;
    for (int i = 0; i < mesh.num_owned; ++i) e = std::max(e, visc[i].norm() * mesh.h[i] / A.norm());
    return mesh.comm.max(e);
  };
  CHECK(error(flow::slab_stiffness_weights(pipe, metrics, mesh)) < 1e-11);
  // The two-point weights of flow::poisson_weights on prisms are not: the test can fail.
  CHECK(error(flow::poisson_weights(pipe, metrics, mesh)) > 1e-3);
}

TEST_CASE("gradient_at gives the boundary nodes the bits of gradient") {
  // The convective outlets' shortcut (flow::BoundaryConditions::advect_outlets) must not change
  // a run: same edges in the same order, so equality is exact, ghost copies included.
  for (std::string type : {"tetra", "hexa", "mixed"}) {
    CAPTURE(type);
    mesh::BoxSpec spec;
    spec.cell_type = mesh::parse_box_cell_type(type);
    spec.cells = {5, 4, 6};
    spec.perturbation = 0.2;
    const auto mesh = local_box(spec, MPI_COMM_WORLD);
    const int n = mesh.num_local();
    VectorField u(n);
    for (int i = 0; i < n; ++i) u[i] = u_exact(mesh.position[i]);
    std::vector<int> nodes;
    for (const auto& b : mesh.boundary) nodes.push_back(b.node);
    TensorField full, part(n, Eigen::Matrix3d::Constant(1e300));  // stale values are replaced
    flow::gradient(mesh, u, full);
    const auto subset = flow::gradient_edges(mesh, nodes);
    CHECK(subset.edges.size() < static_cast<std::size_t>(mesh.num_owned_edges));
    for (int repeat = 0; repeat < 2; ++repeat) flow::gradient_at(mesh, subset, u, part);
    std::int64_t differing = 0;
    for (const int j : nodes) differing += (part[j].array() != full[j].array()).any();
    CHECK(mesh.comm.sum(differing) == 0);
    CHECK(mesh.comm.sum(static_cast<std::int64_t>(nodes.size())) > 0);
  }
}
