// Frictionless penalty contact (structure/contact.hpp): the gap against analytic distances (flat
// and curved master surfaces), no force when separated, the exact tangent against central
// differences of the force (pairs and obstacles, Q1 and Q2), and the force as minus the gradient
// of the penalty energy along rigid translations.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <string>

#include "structure/contact.hpp"
#include "structure/contact_face_box.hpp"
#include "structure/contact_kernel.hpp"
#include "structure/mesh_generators.hpp"

using namespace valsalva::structure;

namespace {

SolidMesh box(HexOrder order, std::array<int, 3> n, const Vec3& lo, const Vec3& hi) {
  return structured_block(order, n,
                          [&](const Vec3& s) { return Vec3(lo + s.cwiseProduct(hi - lo)); });
}

// Lower block [0,1]^2 x [0,0.5] (2x2 elements), upper block [0,1]^2 x [0.5+d, 1+d] (3x3).
SolidMesh two_blocks(HexOrder order, double d) {
  SolidMesh m;
  append_body(m, box(order, {2, 2, 1}, Vec3(0, 0, 0), Vec3(1, 1, 0.5)), "lower_");
  append_body(m, box(order, {3, 3, 1}, Vec3(0, 0, 0.5 + d), Vec3(1, 1, 1 + d)), "upper_");
  return m;
}

ContactPair blocks_pair(const SolidMesh& m) {
  return {"lower-upper", m.surface_set("lower_w1"), m.surface_set("upper_w0")};
}

Eigen::MatrixXd dense(const std::vector<Eigen::Triplet<double>>& t, int n) {
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return Eigen::MatrixXd(K);
}

// max |(f(x + h e_j) - f(x - h e_j)) / 2h + K e_j| / max |K| over all dofs j.
double tangent_error(const Contact& c, const Eigen::Matrix3Xd& x, double h) {
  const int n = static_cast<int>(x.size());
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, x.cols());
  std::vector<Eigen::Triplet<double>> t;
  c.add_forces(x, f, &t);
  const Eigen::MatrixXd K = dense(t, n);
  REQUIRE(K.cwiseAbs().maxCoeff() > 0);
  double err = 0;
  for (int j = 0; j < n; ++j) {
    Eigen::Matrix3Xd xp = x, xm = x;
    xp.data()[j] += h;
    xm.data()[j] -= h;
    Eigen::Matrix3Xd fp = Eigen::Matrix3Xd::Zero(3, x.cols()), fm = fp;
    c.add_forces(xp, fp);
    c.add_forces(xm, fm);
    const Eigen::Matrix3Xd df = (fp - fm) / (2 * h);
    const Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(df.data(), n);
    err = std::max(err, (d + K.col(j)).cwiseAbs().maxCoeff());
  }
  return err / K.cwiseAbs().maxCoeff();
}

// The upper block pushed 0.02 into the lower one, tilted and with randomly moved nodes.
Eigen::Matrix3Xd perturbed(const SolidMesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.003, 0.003);
  Eigen::Matrix3Xd x = m.X;
  for (int n : m.node_set("upper_w0")) x(2, n) -= 0.02;
  for (int n = 0; n < m.num_nodes(); ++n) {
    x(2, n) += 0.01 * x(0, n) - 0.005 * x(1, n);
    for (int k = 0; k < 3; ++k) x(k, n) += u(rng);
  }
  return x;
}

const auto kMaterial = make_linear_elastic(1e3, 0.3);

}  // namespace

TEST_CASE("separated blocks: the gap is their distance and there is no force") {
  for (HexOrder order : {HexOrder::q1, HexOrder::q2}) {
    const double d = 0.05;
    const SolidMesh m = two_blocks(order, d);
    const Contact c(m, *kMaterial, {blocks_pair(m)}, {}, {});
    Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
    std::vector<Eigen::Triplet<double>> t;
    const ContactSummary s = c.add_forces(m.X, f, &t);
    CHECK(s.min_gap == doctest::Approx(d).epsilon(1e-12));
    CHECK(f.cwiseAbs().maxCoeff() == 0.0);
    CHECK(t.empty());
    CHECK(s.force == 0.0);
    CHECK(s.area == 0.0);
    // Beyond the search radius (search_factor * h, h ~ 0.4 here) nothing is seen.
    const SolidMesh far = two_blocks(order, 2.0);
    const Contact cf(far, *kMaterial, {blocks_pair(far)}, {}, {});
    CHECK(std::isinf(cf.add_forces(far.X, f).min_gap));
  }
}

TEST_CASE("gap to a curved Q2 surface against the analytic distance to the cylinder") {
  // Master: a cylindrical shell r in [1, 1.2] over 60..120 degrees (axis z); slave: a flat block
  // whose lower face y = 1.22 lies above it.
  SolidMesh m;
  const double R = 1.2, y0 = 1.22;
  append_body(m,
              structured_block(HexOrder::q2, {2, 6, 1},
                               [](const Vec3& s) {
                                 const double th = M_PI / 3 * (1 + s[1]), r = 1 + 0.2 * s[0];
                                 return Vec3(r * std::cos(th), r * std::sin(th), 0.2 * s[2]);
                               }),
              "shell_");
  append_body(m, box(HexOrder::q2, {2, 1, 1}, Vec3(-0.2, y0, 0), Vec3(0.2, 1.5, 0.2)), "flat_");
  // Shell: u -> radius, v -> angle (counter-clockwise), so the outer surface is u1.
  const Contact c(m, *kMaterial,
                  {{"flat-shell", m.surface_set("flat_v0"), m.surface_set("shell_u1")}}, {}, {});
  int count[2] = {0, 0};
  double err = 0;
  for (const ContactPoint& p : c.points(m.X)) {
    ++count[p.half];
    const double exact = p.half == 0 ? std::hypot(p.x[0], p.x[1]) - R : y0 - p.x[1];
    err = std::max(err, std::abs(p.gap - exact));
  }
  CHECK(count[0] == 2 * 16);  // every slave point of the flat face projects on the shell
  CHECK(count[1] > 0);
  // Q2 interpolation of a 10-degree arc deviates from the circle by ~ R (dtheta)^4 / 400 (< 3e-6).
  MESSAGE("curved gap error " << err);
  CHECK(err < 5e-6);
}

namespace {

// A curved face (Q1 or Q2) of the curved-shell kind: nodes of a cylinder r = 1 over 0..40 degrees
// in s and 0..0.3 in t, plus a fixed wobble so that no coefficient is special.
template <int NF>
std::array<contact_detail::V3<double>, NF> curved_face(const contact_detail::FaceShape<NF>& f) {
  std::array<contact_detail::V3<double>, NF> P;
  for (int a = 0; a < NF; ++a) {
    const double s = f.cs[a], t = f.ct[a], th = 0.35 * (1 + s) / 2;
    P[a] = {std::cos(th) + 0.01 * s * t, std::sin(th), 0.15 * (1 + t) + 0.02 * s * s};
  }
  return P;
}

template <int NF>
void check_newton_evaluation(HexOrder order) {
  using V = contact_detail::V3<double>;
  const contact_detail::FaceShape<NF> f(order, 4);
  const auto P = curved_face(f);
  double err_first = 0, err_second = 0;
  for (double s : {-0.9, -0.2, 0.35, 1.0})
    for (double t : {-1.0, 0.1, 0.7}) {
      V x, xs, xt, xss, xst, xtt, y, ys, yt;
      f.eval_newton(P, s, t, x, xs, xt, xss, xst, xtt);
      f.eval(P, s, t, y, ys, yt);
      for (int i = 0; i < 3; ++i)
        err_first = std::max(
            {err_first, std::abs(x[i] - y[i]), std::abs(xs[i] - ys[i]), std::abs(xt[i] - yt[i])});
      // Second derivatives against central differences of the tangents (exact for quadratics).
      const double h = 1e-3;
      V p, ps_p, pt_p, m, ps_m, pt_m, q, qs, qt_p, r, rs, qt_m;
      f.eval(P, s + h, t, p, ps_p, pt_p);
      f.eval(P, s - h, t, m, ps_m, pt_m);
      f.eval(P, s, t + h, q, qs, qt_p);
      f.eval(P, s, t - h, r, rs, qt_m);
      for (int i = 0; i < 3; ++i)
        err_second = std::max({err_second, std::abs(xss[i] - (ps_p[i] - ps_m[i]) / (2 * h)),
                               std::abs(xst[i] - (pt_p[i] - pt_m[i]) / (2 * h)),
                               std::abs(xtt[i] - (qt_p[i] - qt_m[i]) / (2 * h))});
    }
  CHECK(err_first < 1e-14);
  CHECK(err_second < 1e-9);
}

}  // namespace

TEST_CASE(
    "the projection's one-pass evaluation equals the face's position, tangents and their "
    "derivatives (Q1 and Q2)") {
  check_newton_evaluation<4>(HexOrder::q1);
  check_newton_evaluation<9>(HexOrder::q2);
}

TEST_CASE("projection: a closest point just inside the face is found, one just outside refused") {
  // A flat Q2 face whose node at face coordinates (s, t) sits at (s, t, 0): points above (x, y)
  // project at s = x, t = y, their height the gap's magnitude.
  const contact_detail::FaceShape<9> f(HexOrder::q2, 4);
  std::array<contact_detail::V3<double>, 9> P;
  for (int a = 0; a < 9; ++a) P[a] = {double(f.cs[a]), double(f.ct[a]), 0.0};
  for (double x : {0.3, 0.999, 1.001, 1.02, 1.5, 3.0}) {
    const auto pr = contact_detail::project<9>(f, P, {x, -0.4, 0.05});
    CAPTURE(x);
    CHECK(pr.inside == (x <= 1.0));
    if (pr.inside) {
      CHECK(pr.s == doctest::Approx(x).epsilon(1e-12));
      CHECK(pr.t == doctest::Approx(-0.4).epsilon(1e-12));
      CHECK(std::abs(pr.gap) == doctest::Approx(0.05).epsilon(1e-12));
    }
  }
}

TEST_CASE("face box: holds every point of a curved Q2 face, bounds the distance from below") {
  // Random curved faces (nodes of a warped square, bulging up to a third of its size): sampled
  // face points lie in the box (distance 0), and for random points nearby the box's distance
  // never exceeds the distance to the face (its minimum over a 201 x 201 sample, which
  // overestimates the true distance by at most the sampling's 2e-4 of the face size).
  const contact_detail::FaceShape<9> f(HexOrder::q2, 4);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst_inside = 0, worst_bound = -1, tightest = 1;
  for (int face = 0; face < 20; ++face) {
    std::array<contact_detail::V3<double>, 9> P;
    for (int a = 0; a < 9; ++a) {
      const double s = f.cs[a], t = f.ct[a];
      P[a] = {s + 0.1 * u(rng), t + 0.1 * u(rng), 0.35 * (1 - s * s) * (1 + t) + 0.1 * u(rng)};
    }
    const contact_detail::FaceBox box = contact_detail::face_box<9>(f, P);
    std::vector<contact_detail::V3<double>> sample;
    for (int i = 0; i <= 200; ++i)
      for (int j = 0; j <= 200; ++j) {
        contact_detail::V3<double> x, xs, xt;
        f.eval(P, -1 + i / 100.0, -1 + j / 100.0, x, xs, xt);
        sample.push_back(x);
        worst_inside = std::max(worst_inside, box.distance(x));
      }
    for (int k = 0; k < 50; ++k) {
      const contact_detail::V3<double> y{2 * u(rng), 2 * u(rng), 1.5 * u(rng)};
      double d = HUGE_VAL;
      for (const auto& x : sample)
        d = std::min(d, std::sqrt(contact_detail::dot(contact_detail::minus(y, x),
                                                      contact_detail::minus(y, x))));
      worst_bound = std::max(worst_bound, box.distance(y) - d);
      if (d > 0.1) tightest = std::min(tightest, (d - box.distance(y)) / d);
    }
  }
  CAPTURE(tightest);
  CHECK(worst_inside < 1e-14);
  CHECK(worst_bound <= 0);
}

TEST_CASE("face box: the distance above a flat face is the height, beside it the corner's") {
  // The flat face of the projection test above: nodes at (s, t, 0) for s, t in [-1, 1].
  const contact_detail::FaceShape<9> f(HexOrder::q2, 4);
  std::array<contact_detail::V3<double>, 9> P;
  for (int a = 0; a < 9; ++a) P[a] = {double(f.cs[a]), double(f.ct[a]), 0.0};
  const contact_detail::FaceBox box = contact_detail::face_box<9>(f, P);
  CHECK(box.distance({0.3, -0.4, 0.25}) == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(box.distance({2.0, 3.0, 0.0}) == doctest::Approx(std::sqrt(5.0)).epsilon(1e-14));
  CHECK(box.radius == doctest::Approx(std::sqrt(2.0)).epsilon(1e-14));
}

TEST_CASE("contact tangent equals minus the derivative of the force (central differences)") {
  for (HexOrder order : {HexOrder::q1, HexOrder::q2}) {
    CAPTURE(static_cast<int>(order));
    const SolidMesh m = two_blocks(order, 0.0);
    for (auto form :
         {ContactOptions::Formulation::two_half_pass, ContactOptions::Formulation::two_pass}) {
      ContactOptions opt;
      opt.formulation = form;
      const Contact c(m, *kMaterial, {blocks_pair(m)}, {}, opt);
      const Eigen::Matrix3Xd x = perturbed(m, 3);
      Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
      const ContactSummary s = c.add_forces(x, f);
      REQUIRE(s.surfaces[0].active_points > 0);
      // two_pass: every point's slave force and master reaction cancel; two_half_pass: not exactly.
      const double net = f.rowwise().sum().norm() / s.force;
      MESSAGE("net force / contact force " << net);
      if (form == ContactOptions::Formulation::two_pass) CHECK(net < 1e-13);
      // Central differences with h = 1e-6 (1e-4 of the penetration): truncation ~ h^2 |f'''|,
      // round-off ~ 1e-16 |f| / h; both far below 1e-8 of |K| (measured: ~1e-10).
      const double err = tangent_error(c, x, 1e-6);
      MESSAGE("pair tangent relative error " << err);
      CHECK(err < 1e-8);
    }
  }
  // Obstacles: the lower face of the upper block against a plane and inside a cylinder.
  for (HexOrder order : {HexOrder::q1, HexOrder::q2}) {
    const SolidMesh m = two_blocks(order, 0.0);
    RigidObstacle plane{
        "plane", RigidObstacle::Shape::plane, Vec3(0, 0, 0.5), Vec3(0.1, 0.05, 1), 0,
        true,    m.surface_set("upper_w0")};
    RigidObstacle cyl{
        "cylinder", RigidObstacle::Shape::cylinder, Vec3(0.5, 0.5, 0), Vec3(0, 1, 0.1), 0.52,
        true,       m.surface_set("upper_w0")};
    for (const RigidObstacle& o : {plane, cyl}) {
      CAPTURE(o.name);
      const Contact c(m, *kMaterial, {}, {o}, {});
      const Eigen::Matrix3Xd x = perturbed(m, 5);
      Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
      REQUIRE(c.add_forces(x, f).surfaces[0].active_points > 0);
      const double err = tangent_error(c, x, 1e-6);
      MESSAGE(o.name << " tangent relative error " << err);
      CHECK(err < 1e-8);
    }
  }
}

TEST_CASE("shares of the slave faces sum to the whole contact force; a bad share is refused") {
  // The perturbed blocks in contact, with a rigid wall too, so that both loops are split.
  const SolidMesh m = two_blocks(HexOrder::q2, 0.0);
  RigidObstacle floor;
  floor.name = "floor";
  floor.point = Vec3(0, 0, 0.01);
  floor.faces = m.surface_set("lower_w0");
  const Contact contact(m, *kMaterial, {blocks_pair(m)}, {floor}, {});
  const Eigen::Matrix3Xd x = perturbed(m, 7);
  Eigen::Matrix3Xd whole = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
  contact.add_forces(x, whole);
  REQUIRE(whole.cwiseAbs().maxCoeff() > 0);
  for (int parts : {2, 3}) {
    CAPTURE(parts);
    Eigen::Matrix3Xd sum = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
    int nonzero_shares = 0;
    for (int part = 0; part < parts; ++part) {
      Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
      contact.add_forces(x, f, nullptr, {part, parts});
      nonzero_shares += f.cwiseAbs().maxCoeff() > 0;
      sum += f;
    }
    CHECK(nonzero_shares == parts);  // every share has work
    // Only the order of the sums differs.
    CHECK((sum - whole).cwiseAbs().maxCoeff() < 1e-12 * whole.cwiseAbs().maxCoeff());
  }
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
  CHECK_THROWS_WITH_AS(contact.add_forces(x, f, nullptr, {2, 2}), doctest::Contains("share 2 of 2"),
                       std::invalid_argument);
  CHECK_THROWS_AS(contact.add_forces(x, f, nullptr, {0, 0}), std::invalid_argument);
}

TEST_CASE("clearance: surfaces closer than c feel eps (c - g), farther ones nothing") {
  for (HexOrder order : {HexOrder::q1, HexOrder::q2}) {
    CAPTURE(static_cast<int>(order));
    const double d = 0.05;  // gap between the blocks' flat faces (area 1)
    const SolidMesh m = two_blocks(order, d);
    for (double c : {0.04, 0.1, 0.3}) {
      CAPTURE(c);
      ContactOptions opt;
      opt.clearance = c;
      const Contact contact(m, *kMaterial, {blocks_pair(m)}, {}, opt);
      Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
      const ContactSummary s = contact.add_forces(m.X, f);
      // The reported gap stays the geometric distance.
      CHECK(s.min_gap == doctest::Approx(d).epsilon(1e-12));
      const double eps = s.surfaces[0].penalty;
      const double expected = c > d ? eps * (c - d) : 0.0;  // uniform pressure on area 1
      CHECK(s.max_pressure == doctest::Approx(expected).epsilon(1e-12));
      CHECK(s.force == doctest::Approx(expected).epsilon(1e-10));
      // Each block is pushed away from the other by the whole force.
      CHECK(f.row(2).sum() == doctest::Approx(0.0).scale(expected + 1));
      double upper = 0;
      for (int n = 0; n < m.num_nodes(); ++n)
        if (m.X(2, n) > 0.5 + d / 2) upper += f(2, n);
      CHECK(upper == doctest::Approx(expected).epsilon(1e-10));
    }
    // The tangent stays exact with a clearance (the perturbed blocks of the test above, 0.1 apart
    // plus the perturbation, inside a clearance of 0.15).
    ContactOptions opt;
    opt.clearance = 0.15;
    const SolidMesh apart = two_blocks(order, 0.1);
    const Contact contact(apart, *kMaterial, {blocks_pair(apart)}, {}, opt);
    const Eigen::Matrix3Xd x = perturbed(apart, 3);
    Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, apart.num_nodes());
    REQUIRE(contact.add_forces(x, f).surfaces[0].active_points > 0);
    const double err = tangent_error(contact, x, 1e-6);
    MESSAGE("clearance tangent relative error " << err);
    CHECK(err < 1e-8);
  }
  ContactOptions bad;
  bad.clearance = -1e-3;
  const SolidMesh m = two_blocks(HexOrder::q1, 0.05);
  CHECK_THROWS_WITH_AS(Contact(m, *kMaterial, {blocks_pair(m)}, {}, bad),
                       doctest::Contains("clearance"), std::invalid_argument);
}

TEST_CASE("smoothed penalty: C1 law, the plain law shifted by w / 2 below -w, exact tangent") {
  using contact_detail::penalty_pressure;
  const double eps = 7.0, w = 0.01;
  CHECK(penalty_pressure(0.001, eps, w) == 0.0);
  CHECK(penalty_pressure(0.0, eps, w) == 0.0);
  // Value and slope continuous at g = 0 and g = -w (one-sided differences, step 1e-9 of w).
  const double d = 1e-11;
  for (double g0 : {0.0, -w}) {
    CAPTURE(g0);
    const double below = penalty_pressure(g0 - d, eps, w), above = penalty_pressure(g0 + d, eps, w);
    // A slope of at most eps changes p by 2 eps d over the interval; a jump would be ~eps w.
    CHECK(std::abs(above - below) <= 2.000001 * eps * d);
    const double slope_below =
        (penalty_pressure(g0 - d, eps, w) - penalty_pressure(g0 - 2 * d, eps, w)) / d;
    const double slope_above =
        (penalty_pressure(g0 + 2 * d, eps, w) - penalty_pressure(g0 + d, eps, w)) / d;
    CHECK(std::abs(slope_above - slope_below) < 1e-3 * eps);
  }
  CHECK(penalty_pressure(-3 * w, eps, w) == doctest::Approx(eps * 2.5 * w).epsilon(1e-14));
  CHECK(penalty_pressure(-3 * w, eps, 0.0) == doctest::Approx(eps * 3 * w).epsilon(1e-14));

  // Through Contact: penetrations of 0.01-0.03 against a band of 0.05 h (~0.02) put points on
  // both branches; the automatic-differentiation tangent stays exact.
  const SolidMesh m = two_blocks(HexOrder::q2, 0.0);
  ContactOptions opt;
  opt.smoothing = 0.05;
  const Contact c(m, *kMaterial, {blocks_pair(m)}, {}, opt);
  const Eigen::Matrix3Xd x = perturbed(m, 3);
  const double width = opt.smoothing * c.summary(x).surfaces[0].h;
  int in_band = 0, deep = 0;
  for (const auto& p : c.points(x)) {
    if (p.gap < 0 && p.gap > -width) ++in_band;
    if (p.gap <= -width) ++deep;
  }
  MESSAGE("points in the band " << in_band << ", deeper " << deep);
  REQUIRE(in_band > 0);
  REQUIRE(deep > 0);
  const double err = tangent_error(c, x, 1e-6);
  MESSAGE("smoothed pair tangent relative error " << err);
  CHECK(err < 1e-8);
  ContactOptions bad;
  bad.smoothing = -0.1;
  CHECK_THROWS_WITH_AS(Contact(m, *kMaterial, {blocks_pair(m)}, {}, bad),
                       doctest::Contains("smoothing"), std::invalid_argument);
}

TEST_CASE("obstacle force is minus the gradient of the penalty energy along translations") {
  // Pi = eps/2 int <-g>^2 da; a rigid translation v keeps da and changes g by v . n, so
  // sum_a f_a . v = -dPi/dtau along x + tau v.
  const SolidMesh m = two_blocks(HexOrder::q2, 0.0);
  const RigidObstacle plane{
      "plane", RigidObstacle::Shape::plane, Vec3(0, 0, 0.5), Vec3(0.2, -0.1, 1), 0,
      true,    m.surface_set("upper_w0")};
  const Contact c(m, *kMaterial, {}, {plane}, {});
  const Eigen::Matrix3Xd x = perturbed(m, 7);
  const Vec3 v(0.3, 0.5, -0.8);
  auto energy = [&](double tau) {
    Eigen::Matrix3Xd y = x;
    y.colwise() += tau * v;
    Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
    const double eps = c.add_forces(y, f).surfaces[0].penalty;
    double pi = 0;
    for (const ContactPoint& p : c.points(y))
      if (p.gap < 0) pi += 0.5 * eps * p.gap * p.gap * p.area;
    return pi;
  };
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, m.num_nodes());
  c.add_forces(x, f);
  const double work = (f.transpose() * v).sum();
  const double h = 1e-6;
  const double dpi = (energy(h) - energy(-h)) / (2 * h);
  REQUIRE(std::abs(work) > 0);
  CHECK(work == doctest::Approx(-dpi).epsilon(1e-7));
}

TEST_CASE("contact pairs must belong to different bodies") {
  const SolidMesh m = two_blocks(HexOrder::q1, 0.0);
  CHECK_THROWS_WITH_AS(
      Contact(m, *kMaterial, {{"self", m.surface_set("lower_w1"), m.surface_set("lower_u0")}}, {},
              {}),
      doctest::Contains("node"), std::invalid_argument);
  ContactOptions o;
  o.penalty_factor = -1;
  CHECK_THROWS_WITH_AS(Contact(m, *kMaterial, {blocks_pair(m)}, {}, o),
                       doctest::Contains("penalty_factor"), std::invalid_argument);
}

TEST_CASE("pairs_between: one pair per two bodies, from named surface sets") {
  SolidMesh m;
  for (int i = 0; i < 3; ++i)
    append_body(m, box(HexOrder::q1, {1, 1, 1}, Vec3(2.0 * i, 0, 0), Vec3(2.0 * i + 1, 1, 1)),
                "body" + std::to_string(i) + "_");
  const auto pairs = pairs_between(m, {{"body0_u1", "body0_w1"}, {"body1_u0"}, {"body2_u0"}});
  REQUIRE(pairs.size() == 3);
  CHECK(pairs[0].name == "body0_u1-body1_u0");
  CHECK(pairs[0].a.size() == 2);
  CHECK(pairs[2].name == "body1_u0-body2_u0");
  const Contact c(m, *kMaterial, pairs, {}, {});
  // Faces x = 1 (body0) and x = 2 (body1) are 1 apart, at the search radius (h = 1); body2's
  // face x = 4 is 3 from body0 and 2 from body1, beyond it.
  const ContactSummary s = c.summary(m.X);
  REQUIRE(s.surfaces.size() == 3);
  CHECK(s.surfaces[0].min_gap == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(std::isinf(s.surfaces[1].min_gap));
  CHECK(std::isinf(s.surfaces[2].min_gap));
}
