// Full-stress viscous operator with variable viscosity (flow/viscous_stress.hpp):
// - constant nu and a discretely divergence-free field: equals nu * viscous() to round-off on
//   uniform hexahedra and split tetrahedra; on perturbed tetrahedra the difference (the
//   discrete grad(div) residue) is reported and bounded;
// - manufactured solution with a variable nu and a non-solenoidal field: observed order >= 1.9
//   on hexahedra and >= 1.8 on split tetrahedra (two finest of 8, 16, 32; the corrected
//   Laplacian part is still pre-asymptotic on tetrahedra, see test_operators.cpp);
// - total momentum: sum_j V_j out_j equals the boundary term sum_b nu_b (G_b + G_b^T) A_b to
//   round-off (edge fluxes cancel in pairs), at np = 1 and 2;
// - ProjectionRK4's subgrid hook: called once per stage with that stage's gradient, and a
//   constant nu_sgs = c reproduces the laminar run with nu + c (up to the transpose part).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/operators.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/viscous_stress.hpp"

using namespace valsalva;
using flow::ScalarField;
using flow::TensorField;
using flow::VectorField;

namespace {

constexpr double k = 2 * std::numbers::pi;

using test::local_box;

// Each component independent of its own coordinate: div u = 0, and the discrete divergence
// vanishes too on hexahedra (d/dx of a function of y, z is exactly zero there).
Eigen::Vector3d solenoidal(const Eigen::Vector3d& x) {
  return {std::sin(k * x.y()) * std::cos(k * x.z()), std::sin(k * x.z()) * std::cos(k * x.x()),
          std::sin(k * x.x()) * std::cos(k * x.y())};
}

// Manufactured field (not solenoidal) with its gradient and Hessians, and the viscosity.
struct Manufactured {
  static Eigen::Vector3d u(const Eigen::Vector3d& x) {
    return {std::sin(k * x.x()) * std::cos(k * x.y()), std::cos(k * x.x()) * std::sin(k * x.z()),
            std::sin(k * x.y()) * std::cos(k * x.z())};
  }
  static double nu(const Eigen::Vector3d& x) {
    return 0.3 * (1 + 0.5 * std::cos(k * x.x()) * std::sin(k * x.y()) * std::cos(k * x.z()));
  }
  // div( nu (G + G^T) ) = nu (lap u + grad div u) + (G + G^T) grad nu.
  static Eigen::Vector3d exact(const Eigen::Vector3d& x) {
    const double sx = std::sin(k * x.x()), cx = std::cos(k * x.x());
    const double sy = std::sin(k * x.y()), cy = std::cos(k * x.y());
    const double sz = std::sin(k * x.z()), cz = std::cos(k * x.z());
    Eigen::Matrix3d g;  // (i, j) = d u_i / d x_j
    g << cx * cy, -sx * sy, 0, -sx * sz, 0, cx * cz, 0, cy * cz, -sy * sz;
    g *= k;
    Eigen::Matrix3d h0, h1, h2;  // Hessians of u_0, u_1, u_2
    h0 << -sx * cy, -cx * sy, 0, -cx * sy, -sx * cy, 0, 0, 0, 0;
    h1 << -cx * sz, 0, -sx * cz, 0, 0, 0, -sx * cz, 0, -cx * sz;
    h2 << 0, 0, 0, 0, -sy * cz, -cy * sz, 0, -cy * sz, -sy * cz;
    const std::array<Eigen::Matrix3d, 3> hess{k * k * h0, k * k * h1, k * k * h2};
    Eigen::Vector3d lap, grad_div;
    for (int i = 0; i < 3; ++i) {
      lap[i] = hess[i].trace();
      grad_div[i] = hess[0](0, i) + hess[1](1, i) + hess[2](2, i);
    }
    const Eigen::Vector3d grad_nu =
        0.3 * 0.5 * k * Eigen::Vector3d(-sx * sy * cz, cx * cy * cz, -cx * sy * sz);
    return nu(x) * (lap + grad_div) + (g + g.transpose()) * grad_nu;
  }
};

// The manufactured fields sampled at the local nodes, and viscous_stress applied to them.
struct Applied {
  ScalarField nu;
  VectorField u, out;
  TensorField grad;
};
Applied apply_manufactured(const mesh::LocalMesh& mesh) {
  Applied a;
  for (const auto& x : mesh.position) {
    a.u.push_back(Manufactured::u(x));
    a.nu.push_back(Manufactured::nu(x));
  }
  flow::gradient(mesh, a.u, a.grad);
  flow::viscous_stress(mesh, flow::laplacian_weights(mesh), a.nu, a.u, a.grad, a.out);
  return a;
}

// Volume-weighted L2 error of viscous_stress against the manufactured solution.
double manufactured_error(const mesh::LocalMesh& mesh) {
  const auto a = apply_manufactured(mesh);
  double e = 0;
  for (int i = 0; i < mesh.num_owned; ++i)
    e += mesh.volume[i] * (a.out[i] - Manufactured::exact(mesh.position[i])).squaredNorm();
  return std::sqrt(mesh.comm.sum(e));
}

}  // namespace

TEST_CASE("constant viscosity and a divergence-free field: viscous_stress = nu viscous()") {
  const double nu0 = 0.7;
  for (const auto& kind : test::order_mesh_kinds()) {
    CAPTURE(kind.type);
    CAPTURE(kind.perturbation);
    const auto mesh = local_box(test::periodic_box(kind.type, 8, kind.perturbation));
    const int n = mesh.num_local();
    ScalarField nu(n, nu0), div;
    VectorField u(n), stress, lap;
    TensorField grad;
    for (int i = 0; i < n; ++i) u[i] = solenoidal(mesh.position[i]);
    const auto weights = flow::laplacian_weights(mesh);
    flow::gradient(mesh, u, grad);
    flow::divergence(mesh, u, div);
    flow::viscous(mesh, weights, nu0, u, grad, lap);
    flow::viscous_stress(mesh, weights, nu, u, grad, stress);
    double diff = 0, scale = 0, div_max = 0, grad_max = 0;
    for (int i = 0; i < mesh.num_owned; ++i) {
      diff = std::max(diff, (stress[i] - lap[i]).norm());
      scale = std::max(scale, lap[i].norm());
      div_max = std::max(div_max, std::abs(div[i]));
      grad_max = std::max(grad_max, grad[i].norm());
    }
    const double rel = mesh.comm.max(diff) / mesh.comm.max(scale);
    const double rel_div = mesh.comm.max(div_max) / mesh.comm.max(grad_max);
    MESSAGE(kind.type << " perturbation " << kind.perturbation
                      << ": max |stress - nu lap| / max |nu lap| = " << rel
                      << ", discrete max |div u| / max |grad u| = " << rel_div);
    if (kind.perturbation == 0.0) {
      // Uniform meshes: discretely solenoidal field, commuting operators -> round-off.
      CHECK(rel_div < 1e-13);
      CHECK(rel < 1e-13);
    } else {
      // Perturbed tetrahedra: the field is not discretely solenoidal and the operators do not
      // commute; the transpose part is a discretisation error of the size of the Laplacian's own
      // error at 8 cells per wavelength (measured 0.052 at np 1 and 2; bound with margin).
      CHECK(rel < 0.1);
    }
  }
}

TEST_CASE("variable viscosity, non-solenoidal manufactured solution: second order") {
  struct Kind {
    std::string type;
    double min_order;
  };
  for (const auto& kind : {Kind{"hexa", 1.9}, Kind{"tetra", 1.8}}) {
    CAPTURE(kind.type);
    const std::vector<int> ns = {8, 16, 32};
    std::vector<double> errors;
    for (int n : ns)
      errors.push_back(manufactured_error(local_box(test::periodic_box(kind.type, n))));
    const double order = test::observed_order(errors[1], errors[2], 1.0 / ns[1], 1.0 / ns[2]);
    MESSAGE(kind.type << ": L2 errors " << errors[0] << " " << errors[1] << " " << errors[2]
                      << ", observed order " << order << " (coarse pair "
                      << test::observed_order(errors[0], errors[1], 1.0 / ns[0], 1.0 / ns[1])
                      << ")");
    CHECK(order >= kind.min_order);
  }
}

TEST_CASE("total momentum: the edge fluxes cancel, only the boundary term remains") {
  for (std::string type : {"tetra", "hexa", "mixed"}) {
    CAPTURE(type);
    mesh::BoxSpec spec;
    spec.cell_type = mesh::parse_box_cell_type(type);
    spec.cells = {6, 5, 7};
    spec.length = Eigen::Vector3d(1.0, 0.8, 1.2);
    spec.perturbation = 0.2;
    const auto mesh = local_box(spec);
    const auto [nu, u, out, grad] = apply_manufactured(mesh);
    Eigen::Vector3d total = Eigen::Vector3d::Zero(), boundary = Eigen::Vector3d::Zero();
    double scale = 0;
    for (int i = 0; i < mesh.num_owned; ++i) {
      total += mesh.volume[i] * out[i];
      scale += mesh.volume[i] * out[i].norm();
    }
    for (const auto& b : mesh.boundary)
      if (b.node < mesh.num_owned)
        boundary += nu[b.node] * (grad[b.node] + grad[b.node].transpose()) * b.area;
    for (int d = 0; d < 3; ++d) {
      total[d] = mesh.comm.sum(total[d]);
      boundary[d] = mesh.comm.sum(boundary[d]);
    }
    scale = mesh.comm.sum(scale);
    MESSAGE(type << ": |sum V out - boundary| / sum V |out| = " << (total - boundary).norm() / scale
                 << ", |boundary| / sum V |out| = " << boundary.norm() / scale);
    CHECK(boundary.norm() > 1e-3 * scale);  // the check is not vacuous
    CHECK((total - boundary).norm() < 1e-13 * scale);
  }
}

TEST_CASE("ProjectionRK4 subgrid hook: stage gradients in, nu + nu_sgs in the stress form") {
  // 2D Taylor-Green field on a periodic hexahedral slab; a hook returning a constant
  // nu_sgs = c must give the laminar run with viscosity nu + c up to the transpose part
  // nu grad(div u) of the (not discretely solenoidal) RK stage fields.
  mesh::BoxSpec spec = test::periodic_box("hexa", 16);
  spec.cells = {16, 16, 3};
  spec.length =
      Eigen::Vector3d(2 * std::numbers::pi, 2 * std::numbers::pi, 3 * std::numbers::pi / 8);
  const auto box = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(box);
  const auto mesh =
      mesh::distribute(box, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  const double nu0 = 0.01, c = 0.02, dt = 0.05;
  flow::FlowState initial;
  for (const auto& x : mesh.position) {
    initial.velocity.emplace_back(std::sin(x.x()) * std::cos(x.y()),
                                  -std::cos(x.x()) * std::sin(x.y()), 0.0);
    initial.pressure.push_back(0.25 * (std::cos(2 * x.x()) + std::cos(2 * x.y())));
  }
  flow::ProjectionOptions laminar;
  laminar.viscosity = nu0 + c;
  laminar.poisson.tolerance = 1e-12;
  flow::ProjectionOptions les = laminar;
  les.viscosity = nu0;
  int calls = 0;
  bool stages_in_order = true;  // the hook sees stage = 0, 1, 2, 3 in every step
  double first_grad_error = -1;
  les.subgrid_viscosity = [&](int stage, const TensorField& grad, ScalarField& nu_sgs) {
    stages_in_order = stages_in_order && stage == calls % 4;
    if (calls++ == 0) {  // the first stage sees the gradient of v^n
      TensorField expected;
      flow::gradient(mesh, initial.velocity, expected);
      first_grad_error = 0;
      for (std::size_t i = 0; i < grad.size(); ++i)
        first_grad_error = std::max(first_grad_error, (grad[i] - expected[i]).norm());
    }
    CHECK(nu_sgs.size() == grad.size());
    std::fill(nu_sgs.begin(), nu_sgs.end(), c);
  };
  flow::ProjectionRK4 a(mesh, laminar), b(mesh, les);
  CHECK(a.subgrid_viscosity().empty());
  CHECK(a.max_subgrid_viscosity() == 0.0);
  auto sa = initial, sb = initial;
  double change = 0, diff = 0;
  for (int s = 0; s < 3; ++s) {
    a.step(sa, dt);
    b.step(sb, dt);
  }
  for (int i = 0; i < mesh.num_owned; ++i) {
    change = std::max(change, (sa.velocity[i] - initial.velocity[i]).norm());
    diff = std::max(diff, (sa.velocity[i] - sb.velocity[i]).norm());
  }
  change = mesh.comm.max(change);
  diff = mesh.comm.max(diff);
  MESSAGE("laminar nu + c vs hook nu_sgs = c after 3 steps: max |du| = " << diff << ", max change "
                                                                         << change);
  CHECK(calls == 12);  // 4 stages x 3 steps
  CHECK(stages_in_order);
  CHECK(first_grad_error == 0.0);
  CHECK(b.subgrid_viscosity().size() == static_cast<std::size_t>(mesh.num_local()));
  CHECK(b.max_subgrid_viscosity() == c);
  CHECK(a.subgrid_viscosity().empty());  // laminar: nothing allocated
  CHECK(diff < 1e-3 * change);           // measured 4e-5 (np 1 and 2)
}
