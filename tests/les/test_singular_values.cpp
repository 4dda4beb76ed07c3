// Closed-form singular values (les/singular_values.hpp) against Eigen's JacobiSVD.
#include <doctest/doctest.h>

#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "les/singular_values.hpp"
#include "random_gradients.hpp"

using valsalva::les::singular_values;
using namespace valsalva::les::test;

namespace {
Eigen::Vector3d reference(const Eigen::Matrix3d& g) {
  return Eigen::JacobiSVD<Eigen::Matrix3d>(g).singularValues();
}
}  // namespace

TEST_CASE("singular values match JacobiSVD on 10^4 random gradients to 1e-9 relative") {
  // Gaussian entries times a magnitude 10^[-3, 6] (velocity gradients in 1/s). JacobiSVD itself
  // is accurate to ~eps*sigma1 in absolute terms, so the per-value relative difference grows as
  // sigma1/sigma3; the worst sample here has sigma3/sigma1 ~ 1e-5 (measured max ~ 1e-11).
  std::mt19937_64 rng(20110805);
  std::uniform_real_distribution<double> mag(-3.0, 6.0);
  double worst = 0.0;
  for (int t = 0; t < 10000; ++t) {
    const Eigen::Matrix3d g = gaussian_matrix(rng) * std::pow(10.0, mag(rng));
    const Eigen::Vector3d s = singular_values(g), r = reference(g);
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(s(i) - r(i)) / r(i));
    REQUIRE(s(0) >= s(1));
    REQUIRE(s(1) >= s(2));
    REQUIRE(s(2) >= 0.0);
  }
  MESSAGE("max relative difference over 10^4 random gradients: " << worst);
  CHECK(worst < 1e-9);
}

TEST_CASE("singular values of near-degenerate gradients U diag(s) V^T") {
  // Double and triple singular values (split by 1e-9 and 1e-12), nearly singular and exactly
  // rank-deficient gradients, small pairs (sigma2 ~ sigma3 << sigma1, the deflated branch).
  // Values below 1e-6 sigma1 are compared in absolute terms (round-off of U diag(s) V^T).
  const double cases[][3] = {{1, 1, 0.3},       {1, 1 + 1e-9, 0.3},
                             {1, 0.3, 0.3},     {1, 0.3, 0.3 + 1e-9},
                             {1, 1, 1},         {1, 1 - 1e-12, 1 + 1e-12},
                             {1, 0.5, 1e-6},    {2, 1, 1e-3},
                             {1, 0.5, 0},       {1, 0, 0},
                             {1, 1, 0},         {5, 5, 5},
                             {1, 1e-3, 1e-3},   {1, 1e-3, 1e-3 * (1 + 1e-9)},
                             {1, 0.05, 0.01},   {1, 1e-5, 0},
                             {1, 0.1001, 0.03}, {1, 0.0999, 0.03}};  // both sides of the branch
  std::mt19937_64 rng(85106);
  double worst_rel = 0.0, worst_abs = 0.0;
  for (const auto& c : cases) {
    for (int t = 0; t < 500; ++t) {
      const Eigen::Matrix3d g = random_rotation(rng) *
                                Eigen::Vector3d(c[0], c[1], c[2]).asDiagonal() *
                                random_rotation(rng).transpose();
      const Eigen::Vector3d s = singular_values(g), r = reference(g);
      for (int i = 0; i < 3; ++i) {
        if (r(i) >= 1e-6 * r(0))
          worst_rel = std::max(worst_rel, std::abs(s(i) - r(i)) / r(i));
        else
          worst_abs = std::max(worst_abs, std::abs(s(i) - r(i)) / r(0));
      }
    }
  }
  MESSAGE("near-degenerate: max relative " << worst_rel << ", max absolute/sigma1 " << worst_abs);
  CHECK(worst_rel < 1e-9);
  CHECK(worst_abs < 1e-14);
}

TEST_CASE("singular values: zero, extreme magnitudes and NaN") {
  CHECK(singular_values(Eigen::Matrix3d::Zero()).norm() == 0.0);
  const Eigen::Matrix3d d = Eigen::Vector3d(3.0, 2.0, 1.0).asDiagonal();
  for (double scale : {1e-200, 1e-100, 1.0, 1e100, 1e200}) {
    const Eigen::Vector3d s = singular_values(d * scale);
    CHECK(std::abs(s(0) / scale - 3.0) < 1e-14);
    CHECK(std::abs(s(1) / scale - 2.0) < 1e-14);
    CHECK(std::abs(s(2) / scale - 1.0) < 1e-14);
  }
  Eigen::Matrix3d bad = d;
  bad(1, 2) = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isnan(singular_values(bad)(0)));
  for (int i = 0; i < 9; ++i) {  // a NaN anywhere propagates (never a silent zero viscosity)
    Eigen::Matrix3d b = d;
    b.data()[i] = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(singular_values(b).sum()));
  }
}
