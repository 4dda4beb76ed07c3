// Internal forces and stiffness: patch test on a distorted 3x3x3 patch, zero force in the
// reference state, objectivity, momentum balance, stiffness against central differences,
// allocation-free explicit mode, and nodal stress recovery.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "material_zoo.hpp"
#include "structure/mesh_generators.hpp"
#include "structure/solid_forces.hpp"
#include "structure/stress_recovery.hpp"

// Counts heap allocations made while `g_count_allocs` is set (explicit-mode test).
static std::atomic<bool> g_count_allocs{false};
static std::atomic<long> g_allocs{0};
void* operator new(std::size_t n) {
  if (g_count_allocs) ++g_allocs;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

using namespace valsalva::structure;
using valsalva::structure::testing::material_zoo;

namespace {
// Unit cube split 3x3x3 with every node not on the boundary moved randomly (Q2 mid-nodes too,
// so elements are curved); boundary faces stay planar.
SolidMesh distorted_patch(HexOrder order, unsigned seed) {
  SolidMesh m = structured_block(order, {3, 3, 3}, [](const Vec3& s) { return s; });
  std::mt19937 rng(seed);
  // Up to 0.2 of the node spacing 1/(3 p): distorted but not inverted.
  const double amp = 0.2 / (3 * static_cast<int>(order));
  std::uniform_real_distribution<double> u(-amp, amp);
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k) {
      const double c = m.X(k, n);
      if (c > 1e-12 && c < 1 - 1e-12) m.X(k, n) = c + u(rng);
    }
  m.validate();
  return m;
}
bool on_boundary(const Vec3& X) {
  return (X.array() < 1e-12).any() || (X.array() > 1 - 1e-12).any();
}
Mat3 F0() {
  Mat3 F;
  F << 1.15, 0.1, -0.05, 0.02, 0.93, 0.08, -0.04, 0.06, 1.07;
  return F;
}
}  // namespace

TEST_CASE("patch test: homogeneous deformation of a distorted patch") {
  for (HexOrder order : {HexOrder::q1, HexOrder::q2}) {
    const SolidMesh m = distorted_patch(order, 3);
    for (const auto& z : material_zoo()) {
      CAPTURE(z.name);
      SolidForces forces(m, *z.material);
      const Mat3 F = F0();
      const Eigen::Matrix3Xd x = F * m.X + Vec3(0.3, -0.2, 0.1).replicate(1, m.num_nodes());
      Eigen::Matrix3Xd f(3, m.num_nodes());
      forces.internal_forces(x, f);
      const Mat3 P = z.material->pk1(F);
      // Every interior node is in equilibrium, and the boundary forces balance.
      for (int n = 0; n < m.num_nodes(); ++n)
        if (!on_boundary(m.X.col(n))) CHECK(f.col(n).norm() <= 1e-11 * P.norm());
      CHECK(f.rowwise().sum().norm() <= 1e-11 * P.norm());
      for (int e = 0; e < m.num_elements(); ++e)
        CHECK((forces.deformation_gradient(x, e, Vec3(0.2, -0.5, 0.7)) - F).norm() <= 1e-13);
    }
  }
}

TEST_CASE("zero force in the reference configuration; objectivity of the nodal forces") {
  const SolidMesh m = distorted_patch(HexOrder::q2, 5);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-0.02, 0.02);  // node spacing is 1/6
  Eigen::Matrix3Xd x = m.X;
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k) x(k, n) += u(rng) + (k == 0 ? 0.2 * m.X(0, n) * m.X(0, n) : 0.0);
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  for (const auto& z : material_zoo()) {
    CAPTURE(z.name);
    SolidForces forces(m, *z.material);
    Eigen::Matrix3Xd f(3, m.num_nodes()), fr(3, m.num_nodes());
    forces.internal_forces(m.X, f);
    CHECK(f.norm() <= 1e-12 * z.scale);
    forces.internal_forces(x, f);
    // Translation invariance: the forces add up to zero for every law.
    CHECK(f.rowwise().sum().norm() <= 1e-12 * f.norm());
    if (!z.material->objective()) continue;
    forces.internal_forces(Q * x, fr);
    CHECK((fr - Q * f).norm() <= 1e-12 * f.norm());
    // Rotation invariance: zero total moment.
    Vec3 M = Vec3::Zero();
    for (int n = 0; n < m.num_nodes(); ++n) M += x.col(n).cross(f.col(n));
    CHECK(M.norm() <= 1e-12 * f.norm());
  }
}

TEST_CASE("assembled stiffness equals -df/dx by central differences") {
  SolidMesh m = structured_block(HexOrder::q2, {2, 1, 1}, [](const Vec3& s) {
    return Vec3(2 * s[0], s[1] + 0.2 * s[0] * s[0], 0.5 * s[2]);
  });
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  Eigen::Matrix3Xd x = m.X;
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k) x(k, n) += u(rng) + (k == 0 ? 0.1 * m.X(0, n) : 0.0);
  for (const auto& z : material_zoo()) {
    CAPTURE(z.name);
    SolidForces forces(m, *z.material);
    Eigen::Matrix3Xd f, fp(3, m.num_nodes()), fm(3, m.num_nodes()), f2(3, m.num_nodes());
    Eigen::SparseMatrix<double> K;
    forces.assemble(x, f, K);
    forces.internal_forces(x, f2);
    CHECK((f - f2).norm() <= 1e-13 * f.norm());
    const Eigen::MatrixXd Kd(K);
    Eigen::MatrixXd Kfd(Kd.rows(), Kd.cols());
    const double h = 1e-6;
    for (int j = 0; j < 3 * m.num_nodes(); ++j) {
      Eigen::Matrix3Xd xp = x, xm = x;
      xp(j % 3, j / 3) += h;
      xm(j % 3, j / 3) -= h;
      forces.internal_forces(xp, fp);
      forces.internal_forces(xm, fm);
      Kfd.col(j) = -(Eigen::Map<Eigen::VectorXd>(fp.data(), fp.size()) -
                     Eigen::Map<Eigen::VectorXd>(fm.data(), fm.size())) /
                   (2 * h);
    }
    CHECK((Kd - Kfd).norm() <= 1e-6 * Kd.norm());
    if (z.material->objective() || z.name == "linear_elastic")
      CHECK((Kd - Kd.transpose()).norm() <= 1e-12 * Kd.norm());  // hyperelastic: symmetric
  }
}

TEST_CASE("explicit mode allocates nothing and rejects mismatched sizes") {
  const SolidMesh m = cylindrical_shell_patch(HexOrder::q2, ShellPatch{});
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  SolidForces forces(m, *mat);
  Eigen::Matrix3Xd x = m.X * 1.01, f(3, m.num_nodes());
  g_allocs = 0;
  g_count_allocs = true;
  const double minJ = forces.internal_forces(x, f);
  g_count_allocs = false;
  CHECK(g_allocs == 0);
  CHECK(minJ == doctest::Approx(1.01 * 1.01 * 1.01).epsilon(1e-12));
  Eigen::Matrix3Xd bad(3, 5);
  CHECK_THROWS_WITH_AS(forces.internal_forces(x, bad), doctest::Contains("5 force columns"),
                       std::invalid_argument);
}

TEST_CASE("nodal stresses of a homogeneous state") {
  const SolidMesh m = distorted_patch(HexOrder::q2, 9);
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  SolidForces forces(m, *mat);
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.2;
  const NodalStress s = nodal_stress(forces, F * m.X);
  const Mat3 sigma = mat->pk1(F) * F.transpose() / F.determinant();
  // Uniaxial state: von Mises = |sigma_xx - sigma_yy|; principal strain (1.2^2 - 1)/2.
  for (int n = 0; n < m.num_nodes(); ++n) {
    CHECK(s.von_mises[n] == doctest::Approx(std::abs(sigma(0, 0) - sigma(1, 1))).epsilon(1e-10));
    CHECK(s.principal_stress(0, n) == doctest::Approx(sigma(0, 0)).epsilon(1e-10));
    CHECK(s.principal_strain(0, n) == doctest::Approx(0.22).epsilon(1e-12));
  }
}

TEST_CASE("sum-factorised Q2 forces equal the direct Gauss-point loop for every material") {
  // Curved, distorted Q2 elements (27 of them: the last pack of the batched kernel is partial)
  // and random large deformations: the fast kernel (packs of elements, inline neo-Hookean,
  // pk1 per lane for the other laws) and the direct per-element loop do the same arithmetic in
  // a different order, so they agree to round-off (1e-12 of the largest force).
  const SolidMesh m = distorted_patch(HexOrder::q2, 11);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  for (const auto& z : material_zoo())
    for (std::array<int, 3> rule : {std::array<int, 3>{3, 3, 3}, std::array<int, 3>{3, 3, 2}}) {
      CAPTURE(z.name);
      CAPTURE(rule[2]);
      const SolidForces forces(m, *z.material, rule);
      REQUIRE(forces.sum_factorised());
      for (int state = 0; state < 3; ++state) {
        Eigen::Matrix3Xd x = (Mat3::Identity() + (F0() - Mat3::Identity()) * state) * m.X;
        for (int n = 0; n < m.num_nodes(); ++n)
          for (int k = 0; k < 3; ++k) x(k, n) += u(rng);
        Eigen::Matrix3Xd f(3, m.num_nodes()), fd(3, m.num_nodes());
        const double j1 = forces.internal_forces(x, f);
        const double j2 = forces.internal_forces_direct(x, fd);
        CHECK(j1 == doctest::Approx(j2).epsilon(1e-12));
        CHECK((f - fd).cwiseAbs().maxCoeff() <= 1e-12 * fd.cwiseAbs().maxCoeff());
      }
    }
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  CHECK_FALSE(SolidForces(m, *mat, {2, 2, 2}).sum_factorised());
}

TEST_CASE("fast kernel: an inverted element gives the same minimum det F and non-finite forces") {
  const SolidMesh m = distorted_patch(HexOrder::q2, 13);
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  const SolidForces forces(m, *mat);
  Eigen::Matrix3Xd x = m.X;
  x.row(2) *= -1;  // mirror: every det F = -1
  Eigen::Matrix3Xd f(3, m.num_nodes()), fd(3, m.num_nodes());
  CHECK(forces.internal_forces(x, f) == doctest::Approx(-1).epsilon(1e-12));
  CHECK(forces.internal_forces_direct(x, fd) == doctest::Approx(-1).epsilon(1e-12));
  CHECK_FALSE(f.allFinite());
  CHECK_FALSE(fd.allFinite());
}

TEST_CASE("zero-energy modes of the Gauss rules a thin Q2 shell can use") {
  // The stiffness of a free mesh has exactly the 6 rigid-body null vectors unless the rule is too
  // weak: 3x3x3, 3x3x2 (thickness-reduced) and 2x3x3 are stable; the in-plane reduced 2x2x3 has 12
  // spurious modes on one element and on a patch alike (validation/strip_bending relies on this).
  ShellPatch p;
  p.n_angle = 4;
  p.n_height = 3;
  const SolidMesh patch = cylindrical_shell_patch(HexOrder::q2, p);
  const SolidMesh one = structured_block(HexOrder::q2, {1, 1, 1}, [](const Vec3& s) {
    return Vec3(1.05e-3 * s[0], 1e-3 * s[1], 0.15e-3 * s[2]);
  });
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  auto null_space = [&](const SolidMesh& m, std::array<int, 3> rule) {
    const SolidForces forces(m, *mat, rule);
    Eigen::Matrix3Xd f;
    Eigen::SparseMatrix<double> K;
    forces.assemble(m.X, f, K);
    const Eigen::VectorXd ev =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(K), Eigen::EigenvaluesOnly)
            .eigenvalues();
    return static_cast<int>((ev.cwiseAbs().array() < 1e-10 * ev.cwiseAbs().maxCoeff()).count());
  };
  for (const SolidMesh* m : {&one, &patch}) {
    CHECK(null_space(*m, {3, 3, 3}) == 6);
    CHECK(null_space(*m, {3, 3, 2}) == 6);
    CHECK(null_space(*m, {2, 3, 3}) == 6);
    CHECK(null_space(*m, {2, 2, 3}) == 18);
  }
}
