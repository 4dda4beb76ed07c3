// Issue 21, target 2: the properties that make the collocated projection unable to create
// kinetic energy (Trias, Lehmkuhl, Oliva, Perez-Segarra & Verstappen, J. Comput. Phys. 258,
// 246-267, 2014, sec. 3-4; Felten & Lund, J. Comput. Phys. 215, 465-484, 2006):
// 1. the nodal pressure gradient G is the adjoint of the projection's divergence D,
//    <u, G p>_V = -<D u, p>_V, for the 2nd-order pair (M_j = I at interior nodes: the
//    median-dual identity on simplices and uniform hexahedra); tested with random u (zero at
//    boundary nodes, the walls' condition) and random p. The 4th-order pair (Grad4, Div4) is
//    not adjoint: its mismatch is reported, not asserted (the exact adjoint of Div4 loses its
//    order on perturbed tetrahedra, see the issue-21 note of this branch);
// 2. the wide Laplacian D G is bounded by the compact Poisson matrix L: the largest eigenvalue
//    of L^-1 D G (power iteration) is below 1, so u - G L^-1 D u is a V-symmetric contraction
//    and a projection removes energy, never adds it;
// 3. an inviscid random divergence-free field on 20 % perturbed tetrahedra, stepped at CFL 0.5:
//    the kinetic energy never rises above its initial value (relative 1e-13: round-off of sums
//    over ~1e3 nodes).
// At 1 and 2 ranks (the random fields are functions of the dual-node id).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/operators_order4.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/pressure_poisson.hpp"
#include "flow/projection_rk4.hpp"
#include "mesh/pipe_generator.hpp"

using namespace valsalva;

namespace {

double random_unit(std::uint64_t id, int component) {  // SplitMix64 of (id, component)
  std::uint64_t z = id * 3 + static_cast<std::uint64_t>(component) + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return 2.0 * static_cast<double>(z >> 11) / 9007199254740992.0 - 1.0;
}

template <class T>
double inner(const mesh::LocalMesh& m, const std::vector<T>& a, const std::vector<T>& b) {
  double s = 0;
  for (int i = 0; i < m.num_owned; ++i) {
    if constexpr (std::is_same_v<T, double>)
      s += m.volume[i] * a[i] * b[i];
    else
      s += m.volume[i] * a[i].dot(b[i]);
  }
  return m.comm.sum(s);
}

struct Fields {
  flow::VectorField u;
  flow::ScalarField p;
};

// Random u (zero at boundary nodes) and p with valid ghosts.
Fields random_fields(const mesh::LocalMesh& local) {
  std::vector<char> wall(local.num_local(), 0);
  for (const auto& b : local.boundary) wall[b.node] = 1;
  Fields f{flow::VectorField(local.num_local()), flow::ScalarField(local.num_local())};
  for (int i = 0; i < local.num_local(); ++i) {
    const auto id = static_cast<std::uint64_t>(local.dual_node[i]);
    for (int c = 0; c < 3; ++c) f.u[i][c] = wall[i] ? 0.0 : random_unit(id, c);
    f.p[i] = random_unit(id + 7919, 1);
  }
  return f;
}

}  // namespace

TEST_CASE("the nodal pressure gradient is the adjoint of the projection's divergence") {
  for (const auto& c : test::energy_meshes(false)) {
    const auto metrics = mesh::compute_dual_metrics(c.mesh);
    const auto local =
        mesh::distribute(c.mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
    const auto f = random_fields(local);
    flow::VectorField g;
    flow::ScalarField d;
    flow::gradient(local, f.p, g);
    flow::divergence(local, f.u, d);
    const double scale2 = std::sqrt(inner(local, f.u, f.u) * inner(local, g, g));
    const double mismatch2 = std::abs(inner(local, f.u, g) + inner(local, d, f.p)) / scale2;
    flow::Order4Operators order4(local, flow::poisson_weights(c.mesh, metrics, local));
    order4.gradient(f.p, g);
    order4.divergence(f.u, d);
    const double scale4 = std::sqrt(inner(local, f.u, f.u) * inner(local, g, g));
    const double mismatch4 = std::abs(inner(local, f.u, g) + inner(local, d, f.p)) / scale4;
    MESSAGE(c.name << ": |<u, G p> + <D u, p>| / (|u||G p|) 2nd order " << mismatch2
                   << ", 4th order " << mismatch4);
    CAPTURE(c.name);
    // Round-off of sums of ~1e3-1e4 products of O(1) numbers.
    CHECK(mismatch2 <= 1e-13);
  }
}

TEST_CASE("the approximate projection is a contraction: D G is bounded by the Poisson matrix") {
  for (const auto& c : test::energy_meshes(false)) {
    const auto metrics = mesh::compute_dual_metrics(c.mesh);
    const auto local =
        mesh::distribute(c.mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
    const auto weights = flow::poisson_weights(c.mesh, metrics, local);
    flow::PoissonOptions options;
    options.tolerance = 1e-12;
    options.max_iterations = 1000;
    flow::PressurePoisson poisson(local, weights, options);
    // Power iteration on L^-1 (D G): its eigenvalues are Rayleigh quotients |G p|^2 / p^T K p
    // (K = -V L, symmetric positive semi-definite), all >= 0.
    auto p = random_fields(local).p;
    flow::ScalarField x(local.num_local(), 0.0), wide;
    flow::VectorField g;
    double lambda = 0;
    for (int it = 0; it < 60; ++it) {
      flow::gradient(local, p, g);
      flow::divergence(local, g, wide);
      poisson.solve(wide, x);
      const double norm = std::sqrt(inner(local, x, x));
      lambda = norm / std::sqrt(inner(local, p, p));
      for (int i = 0; i < local.num_local(); ++i) p[i] = x[i] / norm;
    }
    MESSAGE(c.name << ": largest eigenvalue of L^-1 D G " << lambda);
    CAPTURE(c.name);
    CHECK(lambda < 1.0);
  }
}

TEST_CASE("an inviscid random divergence-free field on perturbed tetrahedra never gains energy") {
  const auto mesh = mesh::generate_box(test::periodic_box("tetra", 6, 0.2));
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local =
      mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  for (const std::string scheme : {"central2", "central4"}) {
    flow::ProjectionOptions options;
    options.scheme = flow::parse_convection_kind(scheme);
    options.fourth_order_operators = scheme == "central4";
    options.poisson.tolerance = 1e-13;
    options.poisson.max_iterations = 2000;
    flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));
    flow::FlowState state{random_fields(local).u, flow::ScalarField(local.num_local(), 0.0)};
    flow::ScalarField q(local.num_local(), 0.0);
    solver.project(state.velocity, q);
    const double e0 = inner(local, state.velocity, state.velocity);
    double umax = 0;
    for (int i = 0; i < local.num_owned; ++i) umax = std::max(umax, state.velocity[i].norm());
    const double dt = 0.5 * (1.0 / 6) / local.comm.max(umax);
    double worst = -1;
    for (int s = 0; s < 300; ++s) {
      solver.step(state, dt);
      worst = std::max(worst, inner(local, state.velocity, state.velocity) / e0 - 1);
    }
    const double last = inner(local, state.velocity, state.velocity) / e0 - 1;
    MESSAGE(scheme << ": max over 300 steps of E/E0 - 1 " << worst << ", at the end " << last);
    CAPTURE(scheme);
    CHECK(worst <= 1e-13);
  }
}
