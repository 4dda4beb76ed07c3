// Issue 21, target 1: the convective term's contribution to dE/dt, sum_j V_j u_j . C(u)_j,
// relative to |u| |C(u)| (volume-weighted norms), for random velocity fields made discretely
// divergence-free by the solver's own projection (ProjectionRK4::project, which also gives the
// projected face flux), on periodic uniform hexahedra, split tetrahedra, 20 % perturbed
// tetrahedra and prisms and on a Gmsh Delaunay mesh of a curved pipe (walls: u = 0 at every
// boundary node), for central2 and central4 (+ 4th-order operators), at 1 and 2 ranks.
// Bound 1e-12: the skew-symmetric form is zero in exact arithmetic, so what remains is the
// round-off of sums of ~1e4 products (~1e-16 each relative). The divergence form with the
// nodal-average flux (the operator before issue 21, ConvectionScheme::apply(u, conv)) is
// reported beside it. Also asserted: the projected face flux is divergence-free to the Poisson
// tolerance, and the skew form agrees with the flux form of that flux (consistency).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "field_test_utils.hpp"
#include "flow/convection_scheme.hpp"
#include "flow/face_flux.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "mesh/pipe_generator.hpp"

using namespace valsalva;

namespace {

// A random number in [-1, 1] from a dual-node id (SplitMix64): the same field at any rank count.
double random_unit(std::uint64_t id, int component) {
  std::uint64_t z = id * 3 + static_cast<std::uint64_t>(component) + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return 2.0 * static_cast<double>(z >> 11) / 9007199254740992.0 - 1.0;
}

struct Measure {
  double skew = 0;             // |sum V u.C| / (|u| |C|), the solver's form
  double divergence = 0;       // the same for the divergence form with the nodal-average flux
  double flux_divergence = 0;  // max_j |sum_k F_jk + B_j| / max_j sum_k |F_jk|
  double form_difference = 0;  // |C_skew - C_flux form| / |C_skew|
};

double inner(const mesh::LocalMesh& m, const flow::VectorField& a, const flow::VectorField& b) {
  double s = 0;
  for (int i = 0; i < m.num_owned; ++i) s += m.volume[i] * a[i].dot(b[i]);
  return m.comm.sum(s);
}

double relative_energy_rate(const mesh::LocalMesh& m, const flow::VectorField& u,
                            const flow::VectorField& c) {
  return std::abs(inner(m, u, c)) / std::sqrt(inner(m, u, u) * inner(m, c, c));
}

Measure measure(const mesh::Mesh& mesh, const std::string& scheme) {
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local =
      mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  flow::ProjectionOptions options;
  options.scheme = flow::parse_convection_kind(scheme);
  options.fourth_order_operators = scheme == "central4";
  options.poisson.tolerance = 1e-12;
  options.poisson.max_iterations = 1000;
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));
  std::vector<char> wall(local.num_local(), 0);
  for (const auto& b : local.boundary) wall[b.node] = 1;
  flow::VectorField u(local.num_local());
  for (int i = 0; i < local.num_local(); ++i)
    for (int c = 0; c < 3; ++c)
      u[i][c] = wall[i] ? 0.0 : random_unit(static_cast<std::uint64_t>(local.dual_node[i]), c);
  flow::ScalarField q(local.num_local(), 0.0);
  solver.project(u, q);
  for (int i = 0; i < local.num_local(); ++i)
    if (wall[i]) u[i].setZero();  // the wall condition, as step() imposes it
  solver.set_face_flux(solver.face_flux(), u);
  const flow::EdgeField flux = solver.face_flux();

  Measure r;
  auto convection = flow::make_convection_scheme(options.scheme, local);
  flow::VectorField c_skew, c_div;
  convection->apply(u, flux, c_skew);
  convection->apply(u, c_div);
  r.skew = relative_energy_rate(local, u, c_skew);
  r.divergence = relative_energy_rate(local, u, c_div);

  // Divergence of the face flux (boundary flux of the pre-projection field, zero at walls).
  flow::ScalarField div;
  flow::face_flux_divergence(local, flux, u, div);
  std::vector<double> scale(local.num_local(), 0.0);
  for (int e = 0; e < local.num_owned_edges; ++e) {
    const auto [j, k] = local.edges[e];
    scale[j] += std::abs(flux[e]);
    scale[k] += std::abs(flux[e]);
  }
  double worst = 0, largest = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    worst = std::max(worst, std::abs(div[i]) * local.volume[i]);
    largest = std::max(largest, scale[i]);
  }
  r.flux_divergence = local.comm.max(worst) / local.comm.max(largest);

  // Flux form (1/V_j) sum_k F_jk u_jk (central2's face value) against the skew form.
  if (scheme == "central2") {
    flow::VectorField c_flux(local.num_local(), Eigen::Vector3d::Zero());
    for (int e = 0; e < local.num_owned_edges; ++e) {
      const auto [j, k] = local.edges[e];
      const Eigen::Vector3d f = 0.5 * flux[e] * (u[j] + u[k]);
      c_flux[j] += f;
      c_flux[k] -= f;
    }
    flow::VectorField d(local.num_local());
    for (int i = 0; i < local.num_owned; ++i) d[i] = c_flux[i] / local.volume[i] - c_skew[i];
    r.form_difference = std::sqrt(inner(local, d, d) / inner(local, c_skew, c_skew));
  }
  return r;
}

}  // namespace

TEST_CASE("convective term conserves kinetic energy for projected random fields") {
  for (const auto& c : test::energy_meshes(true)) {
    for (const std::string scheme : {"central2", "central4"}) {
      const Measure r = measure(c.mesh, scheme);
      MESSAGE(c.name << " " << scheme << ": |sum V u.C| / (|u||C|) skew form " << r.skew
                     << ", divergence form with nodal flux " << r.divergence
                     << "; face-flux divergence " << r.flux_divergence << ", skew vs flux form "
                     << r.form_difference);
      CAPTURE(c.name);
      CAPTURE(scheme);
      CHECK(r.skew <= 1e-12);
      // Poisson relative residual 1e-12 on ~1e3 nodes: the flux divergence is of that order.
      CHECK(r.flux_divergence <= 1e-9);
      if (scheme == "central2") CHECK(r.form_difference <= 1e-8);
    }
  }
}
