// Constitutive laws: closed-form homogeneous states, tangent against central differences,
// stress against the derivative of the energy, objectivity and the stress-free reference state.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <random>

#include "material_zoo.hpp"

using namespace valsalva::structure;
using valsalva::structure::testing::material_zoo;

namespace {
Mat3 random_F(std::mt19937& rng, double amp) {
  std::uniform_real_distribution<double> u(-amp, amp);
  Mat3 F;
  do {
    for (int i = 0; i < 9; ++i) F(i / 3, i % 3) = (i / 3 == i % 3 ? 1.0 : 0.0) + u(rng);
  } while (F.determinant() < 0.5);
  return F;
}
Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}
}  // namespace

TEST_CASE("uniaxial, equibiaxial and general diagonal stretch against closed forms") {
  // Closed forms P_ii = dW/dlambda_i are evaluated by different formulas than the code; 1e-10 of
  // the stress scale leaves room for ~1e5 round-off ulps in stiff fibre terms.
  const std::vector<Vec3> stretches = {
      {1.3, 1 / std::sqrt(1.3), 1 / std::sqrt(1.3)},  // isochoric uniaxial
      {1.25, 0.97, 0.97},                             // compressible uniaxial
      {1.2, 1.2, 1 / 1.44},                           // isochoric equibiaxial
      {1.15, 1.15, 0.8},                              // equibiaxial with volume change
      {0.8, 1.1, 1.05}};
  for (const auto& z : material_zoo()) {
    CAPTURE(z.name);
    for (const Vec3& l : stretches) {
      CAPTURE(l.transpose());
      const Mat3 P = z.material->pk1(l.asDiagonal());
      const Vec3 ref = z.dW_dlambda(l);
      for (int i = 0; i < 3; ++i) {
        CHECK(std::abs(P(i, i) - ref[i]) <= 1e-10 * (z.scale + std::abs(ref[i])));
        for (int j = 0; j < 3; ++j)
          if (i != j) CHECK(std::abs(P(i, j)) <= 1e-10 * z.scale);
      }
    }
  }
}

TEST_CASE("simple shear against closed forms") {
  for (const auto& z : material_zoo()) {
    CAPTURE(z.name);
    for (double g : {0.05, 0.3, -0.4}) {
      Mat3 F = Mat3::Identity();
      F(0, 1) = g;
      const Mat3 P = z.material->pk1(F);
      const double ref = z.dW_dgamma(g);
      CHECK(std::abs(P(0, 1) - ref) <= 1e-10 * (z.scale + std::abs(ref)));
      if (z.name == "neo_hookean") {  // Cauchy normal-stress difference sigma11 - sigma22 = G g^2
        const Mat3 sigma = P * F.transpose();
        CHECK(std::abs(sigma(0, 0) - sigma(1, 1) - 2.4e6 * g * g) <= 1e-10 * z.scale);
      }
    }
  }
}

TEST_CASE("tangent dP/dF against central differences at random states") {
  std::mt19937 rng(7);
  for (const auto& z : material_zoo()) {
    CAPTURE(z.name);
    for (int trial = 0; trial < 20; ++trial) {
      Mat3 F = random_F(rng, 0.25);
      if (z.name == "hgo") F(0, 0) += 0.15;  // stretch along the fibres so they are active
      Mat3 P;
      Mat9 A;
      z.material->pk1_tangent(F, P, A);
      CHECK((P - z.material->pk1(F)).norm() <= 1e-12 * P.norm());
      // Step 1e-5: truncation O(h^2 |P'''|) ~ 1e-10 relative, round-off eps/h ~ 1e-11.
      const double h = 1e-5;
      Mat9 Afd;
      Mat3 dW;
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          Mat3 Fp = F, Fm = F;
          Fp(k, L) += h;
          Fm(k, L) -= h;
          const Mat3 dP = (z.material->pk1(Fp) - z.material->pk1(Fm)) / (2 * h);
          for (int i = 0; i < 3; ++i)
            for (int J = 0; J < 3; ++J) Afd(vidx(i, J), vidx(k, L)) = dP(i, J);
          dW(k, L) = (z.material->energy(Fp) - z.material->energy(Fm)) / (2 * h);
        }
      CHECK((A - Afd).norm() <= 1e-6 * A.norm());
      CHECK((dW - P).norm() <= 1e-6 * P.norm());  // P = dW/dF
    }
  }
}

TEST_CASE("objectivity and the stress-free reference configuration") {
  std::mt19937 rng(11);
  for (const auto& z : material_zoo()) {
    CAPTURE(z.name);
    CHECK(z.material->pk1(Mat3::Identity()).norm() <= 1e-12 * z.scale);
    if (!z.material->objective()) continue;  // small-strain law: P(QF) != Q P(F) by design
    for (int trial = 0; trial < 10; ++trial) {
      Mat3 F = random_F(rng, 0.3);
      if (z.name == "hgo") F(0, 0) += 0.15;
      const Mat3 Q = random_rotation(rng);
      const Mat3 P = z.material->pk1(F);
      CHECK((z.material->pk1(Q * F) - Q * P).norm() <= 1e-12 * (P.norm() + z.scale));
    }
  }
}

TEST_CASE("material factory rejects bad input with the key and value") {
  const std::string where = "scene.toml:12 [solid.material]";
  CHECK(make_material(MaterialLaw::neo_hookean, {{"G", 2.4e6}, {"K", 1.6e6}}, where)->name() ==
        "neo_hookean");
  CHECK_THROWS_WITH_AS(make_material(MaterialLaw::neo_hookean, {{"G", 2.4e6}, {"k", 1.6e6}}, where),
                       doctest::Contains("scene.toml:12 [solid.material]: unknown parameter 'k'"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_material(MaterialLaw::neo_hookean, {{"G", -1.0}, {"K", 1.6e6}}, where),
                       doctest::Contains("'G' = -1"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_material(MaterialLaw::st_venant_kirchhoff, {{"E", 1e6}}, where),
                       doctest::Contains("needs parameter 'nu'"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(parse_material_law("rubber"),
                       doctest::Contains("unknown material type 'rubber'"), std::invalid_argument);
}
