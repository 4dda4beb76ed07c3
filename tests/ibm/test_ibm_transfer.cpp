// Spreading and interpolation on perturbed tetrahedral boxes distributed over 1, 2 and 3 ranks,
// with markers on a sphere crossing the partition boundaries and markers on and near the walls
// (edges and corners included): partition of unity and zero first moment of the corrected
// kernel, conservation of total force and torque by spreading, exact interpolation of linear
// fields, <Spread F, u>_V = <F, Interp u>, independence of the rank count (against the same mesh
// on one rank), the errors for markers outside the mesh and for too few ghost layers, and the
// order of convergence of interpolation.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/comm.hpp"
#include "core/compensated_sum.hpp"
#include "ibm/dirac_transfer.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

using namespace valsalva;
using Vec = Eigen::Vector3d;

namespace {

const Vec kLength(1.0, 0.8, 0.6);

mesh::Mesh box(int n, bool periodic_z = false) {
  mesh::BoxSpec spec;
  spec.periodic = {false, false, periodic_z};
  spec.cell_type = mesh::BoxCellType::tetra;
  spec.cells = {n, n * 4 / 5, n * 3 / 5};
  spec.length = kLength;
  spec.perturbation = 0.2;
  return mesh::generate_box(spec);
}

// A sphere of markers crossing the partition boundaries, plus markers on and near the walls:
// on a face, 0.05 and 0.3 cells inside, on an edge and in a corner.
std::vector<Vec> markers(double cell) {
  std::vector<Vec> x;
  const Vec centre = 0.5 * kLength;
  const int n = 12;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double theta = std::numbers::pi * (i + 0.5) / n, p = std::numbers::pi * j / n;
      x.push_back(centre + 0.22 * Vec(std::sin(theta) * std::cos(p), std::sin(theta) * std::sin(p),
                                      std::cos(theta)));
    }
  for (double d : {0.0, 0.05, 0.3}) {
    x.emplace_back(d * cell, 0.37, 0.29);                // xmin face
    x.emplace_back(0.61, kLength.y() - d * cell, 0.21);  // ymax face
    x.emplace_back(0.45, 0.52, d * cell);                // zmin face
    x.emplace_back(d * cell, d * cell, 0.33);            // edge
    x.push_back(kLength - Vec::Constant(d * cell));      // corner
  }
  return x;
}

std::vector<Vec> random_forces(std::size_t n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> f(n);
  for (auto& v : f) v = Vec(u(rng), u(rng), u(rng));
  return f;
}

Vec smooth(const Vec& x) {
  return Vec(std::sin(3 * x.x()) * std::cos(2 * x.y()), std::exp(x.z()) * x.x(),
             std::cos(x.x() + 2 * x.z()) + x.y() * x.y());
}

struct Level {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  explicit Level(int n, bool periodic_z = false)
      : mesh(box(n, periodic_z)), metrics(mesh::compute_dual_metrics(mesh)) {}
};

double global_sum(const core::Comm& comm, core::CompensatedSum s) {
  return comm.sum(s.value());
}

// All identities for the three kernels. With a z-periodic mesh the torque (ill-defined across
// periods) is skipped and the linear field is taken independent of z.
void check_identities(const Level& level, const std::vector<Vec>& x, bool periodic_z) {
  auto local = mesh::distribute(level.mesh, level.metrics, MPI_COMM_WORLD,
                                {5, mesh::PartitionMethod::metis});
  const auto& comm = local.comm;
  const auto nm = x.size();

  for (auto type : {ibm::KernelType::peskin4, ibm::KernelType::roma3, ibm::KernelType::bspline3}) {
    CAPTURE(ibm::kernel_name(type));
    ibm::DiracTransfer transfer(local, {{type, 4.0}});
    transfer.locate(x);

    // Every marker is evaluated by exactly one rank.
    CHECK(comm.sum(static_cast<std::int64_t>(transfer.supports().size())) ==
          static_cast<std::int64_t>(nm));

    // Partition of unity and zero first moment of the corrected kernel.
    double worst0 = 0, worst1 = 0;
    for (const auto& s : transfer.supports()) {
      core::CompensatedSum zeroth;
      Vec first = Vec::Zero();
      for (int k = s.begin; k < s.end; ++k) {
        const auto& w = transfer.weights()[k];
        zeroth.add(w.phi * local.volume[w.node]);
        first += w.offset * w.phi * local.volume[w.node];
      }
      worst0 = std::max(worst0, std::abs(zeroth.value() - 1));
      worst1 = std::max(worst1, first.norm() / s.h);
    }
    CHECK(comm.max(worst0) < 1e-12);
    CHECK(comm.max(worst1) < 1e-12);
    // Weights whose node is used at a periodic image: some, exactly when the mesh is periodic.
    std::int64_t wrapped = 0;
    for (const auto& s : transfer.supports())
      for (int k = s.begin; k < s.end; ++k) {
        const auto& w = transfer.weights()[k];
        wrapped += (w.offset - (local.position[w.node] - x[s.marker])).norm() > 1e-9;
      }
    wrapped = comm.sum(wrapped);
    CHECK((periodic_z ? wrapped > 0 : wrapped == 0));
    const double w0 = comm.max(worst0), w1 = comm.max(worst1);

    // Spreading conserves total force and torque.
    const auto force = random_forces(nm);
    std::vector<Vec> density(local.num_local());
    transfer.spread(force, density);
    Vec total_f = Vec::Zero(), total_t = Vec::Zero(), ref_f = Vec::Zero(), ref_t = Vec::Zero();
    double scale_f = 0, scale_t = 0;
    for (std::size_t i = 0; i < nm; ++i) {
      ref_f += force[i];
      ref_t += x[i].cross(force[i]);
      scale_f += force[i].norm();
      scale_t += x[i].norm() * force[i].norm();
    }
    for (int j = 0; j < local.num_owned; ++j) {
      total_f += density[j] * local.volume[j];
      total_t += local.position[j].cross(density[j]) * local.volume[j];
    }
    for (int d = 0; d < 3; ++d) {
      CHECK(std::abs(comm.sum(total_f[d]) - ref_f[d]) < 1e-12 * scale_f);
      if (!periodic_z) CHECK(std::abs(comm.sum(total_t[d]) - ref_t[d]) < 1e-12 * scale_t);
    }

    // Linear fields are interpolated exactly (ghosts start wrong: interpolate refreshes them).
    const Vec a(0.3, -1.2, 2.0);
    Eigen::Matrix3d b;
    b << 1.0, -0.5, 0.25, 2.0, 0.7, -1.1, -0.4, 0.9, 1.6;
    if (periodic_z) b.col(2).setZero();
    std::vector<Vec> field(local.num_local(), Vec::Constant(1e3));
    for (int j = 0; j < local.num_owned; ++j) field[j] = a + b * local.position[j];
    std::vector<Vec> at_markers(nm);
    transfer.interpolate(field, at_markers);
    double worst_linear = 0;
    for (std::size_t i = 0; i < nm; ++i)
      worst_linear = std::max(worst_linear, (at_markers[i] - (a + b * x[i])).norm() / a.norm());
    CHECK(worst_linear < 1e-12);

    // Adjointness with a nonlinear field: <Spread F, u>_V = <F, Interp u>.
    for (int j = 0; j < local.num_owned; ++j) field[j] = smooth(local.position[j]);
    transfer.interpolate(field, at_markers);
    core::CompensatedSum eulerian, lagrangian, size;
    for (int j = 0; j < local.num_owned; ++j) {
      eulerian.add(local.volume[j] * density[j].dot(field[j]));
      size.add(local.volume[j] * density[j].norm() * field[j].norm());
    }
    for (std::size_t i = 0; i < nm; ++i) lagrangian.add(force[i].dot(at_markers[i]));
    CHECK(std::abs(global_sum(comm, eulerian) - lagrangian.value()) <
          1e-12 * global_sum(comm, size));

    // The same on one rank (each rank builds the undistributed mesh): results agree to
    // round-off, node by node (matched through the replicated dual-node index).
    auto serial = mesh::distribute(level.mesh, level.metrics, MPI_COMM_SELF,
                                   {5, mesh::PartitionMethod::metis});
    ibm::DiracTransfer one(serial, {{type, 4.0}});
    one.locate(x);
    std::vector<Vec> density1(serial.num_local()), field1(serial.num_local()), at1(nm);
    one.spread(force, density1);
    for (int j = 0; j < serial.num_local(); ++j) field1[j] = smooth(serial.position[j]);
    one.interpolate(field1, at1);
    std::vector<int> serial_of_dual(level.metrics.volume.size(), -1);
    for (int j = 0; j < serial.num_local(); ++j) serial_of_dual[serial.dual_node[j]] = j;
    double max_f = 0, diff_f = 0, diff_u = 0;
    for (int j = 0; j < local.num_owned; ++j) {
      const auto& ref = density1[serial_of_dual[local.dual_node[j]]];
      max_f = std::max(max_f, ref.norm());
      diff_f = std::max(diff_f, (density[j] - ref).norm());
    }
    for (std::size_t i = 0; i < nm; ++i) diff_u = std::max(diff_u, (at_markers[i] - at1[i]).norm());
    CHECK(comm.max(diff_f) < 1e-12 * comm.max(max_f));
    CHECK(diff_u < 1e-13);
    const double adjoint =
        std::abs(global_sum(comm, eulerian) - lagrangian.value()) / global_sum(comm, size);
    const double rank_f = comm.max(diff_f) / comm.max(max_f);
    if (comm.root())
      MESSAGE(
          fmt::format("{}{} ranks {}: |sum phi V - 1| {:.2e}, |first moment|/h {:.2e}, "
                      "linear {:.2e}, adjoint {:.2e}, vs 1 rank: f {:.2e}, U {:.2e}",
                      periodic_z ? "periodic z, " : "", ibm::kernel_name(type), comm.size(), w0, w1,
                      worst_linear, adjoint, rank_f, diff_u));
  }
}

}  // namespace

TEST_CASE("RKPM spreading and interpolation identities across ranks") {
  const int n = 10;
  check_identities(Level(n), markers(kLength.x() / n), false);
}

TEST_CASE("periodic images: supports wrap across a periodic direction") {
  // Markers on, near and 0.3 cells from both periodic planes, and the sphere.
  auto x = markers(kLength.x() / 10);
  for (double z : {0.0, 0.004, 0.03, kLength.z() - 0.03, kLength.z() - 0.004})
    for (double y : {0.0, 0.33, kLength.y()}) x.emplace_back(0.47, y, z);
  check_identities(Level(10, true), x, true);
}

TEST_CASE("locating again after the markers move gives the supports of a fresh transfer") {
  const int n = 10;
  const Level level(n);
  auto local = mesh::distribute(level.mesh, level.metrics, MPI_COMM_WORLD,
                                {5, mesh::PartitionMethod::metis});
  auto x = markers(kLength.x() / n);
  ibm::DiracTransfer moving(local);
  moving.locate(x);
  const auto before = local.comm.sum(static_cast<std::int64_t>(moving.weights().size()));
  for (auto& p : x) p = 0.5 * kLength + 0.8 * (p - 0.5 * kLength) + Vec(0.03, -0.02, 0.01);
  moving.locate(x);
  ibm::DiracTransfer fresh(local);
  fresh.locate(x);
  REQUIRE(moving.supports().size() == fresh.supports().size());
  REQUIRE(moving.weights().size() == fresh.weights().size());
  int differ = 0;
  for (std::size_t k = 0; k < fresh.weights().size(); ++k)
    differ += moving.weights()[k].node != fresh.weights()[k].node ||
              moving.weights()[k].phi != fresh.weights()[k].phi;
  CHECK(differ == 0);
  CHECK(local.comm.sum(static_cast<std::int64_t>(moving.weights().size())) != before);
}

TEST_CASE("errors name the marker: outside the mesh, too few ghost layers, ill-conditioned") {
  const int n = 10;
  const double cell = kLength.x() / n;
  const Level level(n);
  auto local = mesh::distribute(level.mesh, level.metrics, MPI_COMM_WORLD,
                                {5, mesh::PartitionMethod::metis});
  ibm::DiracTransfer transfer(local);
  std::vector<Vec> x = markers(cell);
  x.emplace_back(5.0, 0.1, 0.1);
  CHECK_THROWS_WITH_AS(transfer.locate(x), doctest::Contains("marker 303 at (5, 0.1, 0.1)"),
                       std::runtime_error);

  // 0.9 cells beyond the xmin wall: refused by default (max_outside 0.5 h), naming the patch.
  const std::vector<Vec> outside{Vec(-0.9 * cell, 0.41, 0.27)};
  CHECK_THROWS_WITH_AS(transfer.locate(outside),
                       doctest::Contains("marker 0 at (-0.09, 0.41, 0.27) m lies 0.09 m (1.12 h) "
                                         "beyond the fluid boundary 'xmin'"),
                       std::runtime_error);
  // 0.3 cells beyond (0.37 h): accepted, like a clamped edge drawn on a curved wall.
  transfer.locate(std::vector<Vec>{Vec(-0.3 * cell, 0.41, 0.27)});
  CHECK(local.comm.sum(static_cast<std::int64_t>(transfer.supports().size())) == 1);
  // Accepted that far out, the 4h support holds only the coplanar wall nodes, so M is singular;
  // one growth (x1.5) reaches the first interior layer.
  ibm::DiracTransfer lenient(local, {{}, 1e-6, 2, 1.5, 2.0});
  lenient.locate(outside);
  int grown = 0;
  for (const auto& s : lenient.supports()) grown += s.width == doctest::Approx(6.0);
  CHECK(local.comm.sum(static_cast<std::int64_t>(grown)) == 1);
  ibm::DiracTransfer rigid(local, {{}, 1e-6, 0, 1.5, 2.0});
  CHECK_THROWS_WITH_AS(rigid.locate(outside),
                       doctest::Contains("marker 0 at (-0.09, 0.41, 0.27) m: the kernel's moment "
                                         "matrix is ill-conditioned"),
                       std::runtime_error);

  // One ghost layer cannot hold a 4h support across a partition boundary.
  if (local.comm.size() > 1) {
    auto thin = mesh::distribute(level.mesh, level.metrics, MPI_COMM_WORLD,
                                 {1, mesh::PartitionMethod::metis});
    ibm::DiracTransfer short_halo(thin);
    CHECK_THROWS_WITH_AS(short_halo.locate(markers(cell)),
                         doctest::Contains("reaches the edge of rank"), std::runtime_error);
  }
}

TEST_CASE("interpolation converges at second order on perturbed tetrahedra") {
  // Markers at fixed physical positions: the sphere and points 0.01 m from the walls.
  std::vector<Vec> x = markers(0.0);
  for (const auto& p : markers(0.0))
    x.push_back(p.cwiseMax(Vec::Constant(0.01)).cwiseMin(kLength - Vec::Constant(0.01)));
  std::vector<double> error;
  for (int n : {8, 16, 32}) {
    const Level level(n);
    auto local = mesh::distribute(level.mesh, level.metrics, MPI_COMM_WORLD,
                                  {5, mesh::PartitionMethod::metis});
    ibm::DiracTransfer transfer(local);
    transfer.locate(x);
    std::vector<Vec> field(local.num_local()), at(x.size());
    for (int j = 0; j < local.num_owned; ++j) field[j] = smooth(local.position[j]);
    transfer.interpolate(field, at);
    double e = 0;
    for (std::size_t i = 0; i < x.size(); ++i) e = std::max(e, (at[i] - smooth(x[i])).norm());
    error.push_back(e);
  }
  const double order_coarse = std::log2(error[0] / error[1]);
  const double order_fine = std::log2(error[1] / error[2]);
  if (core::Comm().root())
    MESSAGE(fmt::format("max interpolation error {:.3e} {:.3e} {:.3e}, order {:.3f} {:.3f}",
                        error[0], error[1], error[2], order_coarse, order_fine));
  // Linear reproduction gives O(h^2). Measured (peskin4, width 4h, max over 606 markers, 1-3
  // ranks alike): 5.705e-2, 1.545e-2, 3.329e-3 with 8, 16, 32 cells along the 1 m side:
  // orders 1.885 and 2.214.
  CHECK(order_coarse >= 1.8);
  CHECK(order_fine >= 1.8);
}

// relocate keeps every support while all markers stay within reuse_distance h of where they
// were built, and rebuilds all of them once one moved farther (markers located at different
// times would lag their kernels differently, and forces that cancel between nearby markers would
// no longer cancel). Kept, the results are bit for bit those of a locate at the old positions;
// rebuilt, those of a locate at the new ones; at 1, 2 and 3 ranks.
TEST_CASE("relocate: all supports kept within reuse_distance h, all rebuilt beyond") {
  const Level level(12);
  auto local = mesh::distribute(level.mesh, level.metrics, MPI_COMM_WORLD,
                                {5, mesh::PartitionMethod::metis});
  const double cell = kLength.x() / 12, reuse = 0.1;
  const auto x = markers(cell);
  const auto nm = x.size();
  ibm::TransferOptions o{{ibm::KernelType::peskin4, 4.0}};
  o.reuse_distance = reuse;
  ibm::DiracTransfer transfer(local, o);
  transfer.locate(x);
  double h_min = 1e300;  // the smallest h a support was built with
  for (const auto& s : transfer.supports()) h_min = std::min(h_min, s.h);
  h_min = local.comm.min(h_min);
  const auto force = random_forces(nm);
  std::vector<Vec> field(local.num_local());
  for (int j = 0; j < local.num_local(); ++j) field[j] = smooth(local.position[j]);
  // Spread and interpolation of `t` against a fresh transfer located at `at`: identical?
  auto same_as_fresh = [&](ibm::DiracTransfer& t, const std::vector<Vec>& at) {
    ibm::DiracTransfer fresh(local, o);
    fresh.locate(at);
    std::vector<Vec> d1(local.num_local()), d2(local.num_local()), u1(nm), u2(nm);
    t.spread(force, d1);
    fresh.spread(force, d2);
    t.interpolate(field, u1);
    fresh.interpolate(field, u2);
    bool same = u1 == u2;
    for (int j = 0; j < local.num_local(); ++j) same = same && d1[j] == d2[j];
    return local.comm.min(same ? 1.0 : 0.0) == 1.0;
  };
  auto shifted = [&](double distance) {  // every marker moved inwards by `distance`
    std::vector<Vec> y = x;
    for (auto& p : y) p += distance * (0.5 * kLength - p).normalized();
    return y;
  };

  const auto small = shifted(0.5 * reuse * h_min);
  transfer.relocate(small);
  CHECK(transfer.counts().rebuilt == static_cast<std::int64_t>(nm));  // the first locate only
  CHECK(transfer.located_at() == x);
  CHECK(same_as_fresh(transfer, x));

  auto one_far = small;
  one_far[7] = shifted(3 * reuse * h_min)[7];
  transfer.relocate(one_far);
  CHECK(transfer.counts().rebuilt == 2 * static_cast<std::int64_t>(nm));
  CHECK(transfer.located_at() == one_far);
  CHECK(same_as_fresh(transfer, one_far));
  CHECK(transfer.counts().calls == 3);

  o.reuse_distance = 0;  // every call rebuilds
  ibm::DiracTransfer always(local, o);
  always.locate(x);
  always.relocate(x);
  CHECK(always.counts().rebuilt == 2 * static_cast<std::int64_t>(nm));
}
