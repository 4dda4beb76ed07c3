// Q1/Q2 hexahedra: node order against the Gmsh library itself, shape-function identities,
// Gauss-rule exactness, and the generated shell/bar geometry against closed-form volumes.
#include <doctest/doctest.h>
#include <gmsh.h>

#include <cmath>
#include <numeric>

#include "structure/mesh_generators.hpp"
#include "tests/structure/solid_volume.hpp"

using namespace valsalva::structure;

TEST_CASE("hex node order matches Gmsh's reference element") {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  for (auto [type, order] : {std::pair{5, HexOrder::q1}, std::pair{12, HexOrder::q2}}) {
    std::string name;
    int dim, ord, nn, npv;
    std::vector<double> coords;
    gmsh::model::mesh::getElementProperties(type, name, dim, ord, nn, coords, npv);
    REQUIRE(nn == hex_node_count(order));
    for (int a = 0; a < nn; ++a)
      for (int k = 0; k < 3; ++k) CHECK(coords[3 * a + k] == hex_reference_node(order, a)[k]);
  }
  gmsh::finalize();
}

TEST_CASE("shape functions: Kronecker delta, partition of unity, derivatives") {
  for (HexOrder order : {HexOrder::q1, HexOrder::q2}) {
    const int nen = hex_node_count(order);
    std::vector<double> N(nen), dN(3 * nen), Np(nen), Nm(nen), tmp(3 * nen);
    for (int b = 0; b < nen; ++b) {
      hex_shape(order, hex_reference_node(order, b), N, dN);
      for (int a = 0; a < nen; ++a) CHECK(N[a] == doctest::Approx(a == b ? 1.0 : 0.0));
    }
    const Vec3 xi(0.31, -0.72, 0.18);
    hex_shape(order, xi, N, dN);
    CHECK(std::accumulate(N.begin(), N.end(), 0.0) == doctest::Approx(1.0).epsilon(1e-14));
    const double h = 1e-6;
    for (int k = 0; k < 3; ++k) {
      Vec3 p = xi, m = xi;
      p[k] += h;
      m[k] -= h;
      hex_shape(order, p, Np, tmp);
      hex_shape(order, m, Nm, tmp);
      // Central difference of a polynomial of degree <= 2 per direction is exact up to round-off.
      for (int a = 0; a < nen; ++a)
        CHECK(std::abs((Np[a] - Nm[a]) / (2 * h) - dN[3 * a + k]) < 1e-9);
    }
  }
}

TEST_CASE("Gauss rules integrate polynomials exactly") {
  // n points integrate degree 2n-1 exactly: int x^4 y^2 z^6 over the cube = (2/5)(2/3)(2/7).
  const QuadratureRule q = gauss_hex({3, 2, 4});
  double s = 0;
  for (int g = 0; g < q.size(); ++g)
    s += q.weights[g] * std::pow(q.points[g][0], 4) * std::pow(q.points[g][1], 2) *
         std::pow(q.points[g][2], 6);
  CHECK(s == doctest::Approx(2.0 / 5 * 2.0 / 3 * 2.0 / 7).epsilon(1e-14));
  CHECK_THROWS_WITH_AS(gauss_hex({5, 1, 1}), doctest::Contains("only 1..4"), std::invalid_argument);
}

using testing::solid_volume;

TEST_CASE("cylindrical shell patch: volume, sets, convergence of the Q2 geometry") {
  ShellPatch p;
  p.n_angle = 8;
  p.n_height = 4;
  p.n_thickness = 2;
  const double exact =
      0.5 * p.angle * p.height *
      (std::pow(p.radius + p.thickness / 2, 2) - std::pow(p.radius - p.thickness / 2, 2));
  // Chord error of the 15-degree Q2 arc segments ~ (dtheta)^4: relative 1e-5 bound.
  const SolidMesh q2 = cylindrical_shell_patch(HexOrder::q2, p);
  CHECK(std::abs(solid_volume(q2) / exact - 1) < 1e-5);
  const SolidMesh q1 = cylindrical_shell_patch(HexOrder::q1, p);
  // Q1 replaces each 15-degree arc by its chord: volume ratio sin(d)/d, d = 15 degrees.
  const double d = p.angle / p.n_angle;
  CHECK(solid_volume(q1) / exact == doctest::Approx(std::sin(d) / d).epsilon(1e-12));
  CHECK(q2.num_elements() == 64);
  CHECK(q2.num_nodes() == 17 * 9 * 5);
  CHECK(q2.node_set("attachment").size() == 17 * 5);
  CHECK(q2.surface_set("outer").size() == 32);
  for (int n : q2.surface_nodes("outer"))
    CHECK(std::hypot(q2.X(0, n), q2.X(1, n)) == doctest::Approx(p.radius + p.thickness / 2));
  CHECK_THROWS_WITH_AS(q2.node_set("nope"), doctest::Contains("no node set 'nope'"),
                       std::invalid_argument);
}

TEST_CASE("straight bar and validation of inverted elements") {
  Bar b;
  b.length = 2;
  b.height = 0.3;
  b.depth = 0.1;
  b.n_length = 5;
  SolidMesh m = straight_bar(HexOrder::q2, b);
  CHECK(solid_volume(m) == doctest::Approx(0.06).epsilon(1e-13));
  CHECK(m.surface_nodes("tip").size() == 9);
  m.X.row(2) *= -1;  // mirror image: every element left-handed
  CHECK_THROWS_WITH_AS(m.validate(), doctest::Contains("element 0"), std::runtime_error);
}
