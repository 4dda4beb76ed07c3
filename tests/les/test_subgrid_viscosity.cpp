// The flow solver's adaptor les::SubgridViscosity: per-node filter widths, default constants,
// both gradient layouts, and clear errors.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "les/subgrid_viscosity.hpp"

using valsalva::les::SubgridViscosity;

TEST_CASE("SubgridViscosity applies the model with each node's filter width") {
  // Pure shear du/dy = s: |S| = s, so Smagorinsky gives (C_s Delta)^2 s exactly.
  const double s = 40.0;
  Eigen::Matrix3d shear = Eigen::Matrix3d::Zero();
  shear(0, 1) = s;
  const std::vector<double> delta = {1e-3, 2e-3, 5e-4};
  const std::vector<Eigen::Matrix3d> grad(3, shear);
  std::vector<double> nu(3);
  SubgridViscosity smag("smagorinsky", {}, delta);
  CHECK(smag.active());
  CHECK(smag.model().constant == doctest::Approx(0.17));
  smag(grad, nu);
  for (int i = 0; i < 3; ++i)
    CHECK(nu[i] == doctest::Approx(std::pow(0.17 * delta[i], 2) * s).epsilon(1e-14));

  // Sigma vanishes for pure shear; a generic gradient gives the same value from the flat layout.
  SubgridViscosity sigma("sigma", 0.0, delta);  // 0 = default constant
  CHECK(sigma.model().constant == doctest::Approx(1.35));
  sigma(grad, nu);
  for (double v : nu) CHECK(std::abs(v) < 1e-12 * s * 1e-6);
  Eigen::Matrix3d g;
  g << 1.0, -2.0, 0.5, 3.0, 0.2, -1.1, 0.7, 1.9, -1.2;
  const std::vector<Eigen::Matrix3d> generic(3, g);
  std::vector<double> flat;
  for (int n = 0; n < 3; ++n)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) flat.push_back(g(i, j));
  std::vector<double> nu_flat(3);
  sigma(generic, nu);
  sigma(std::span<const double>(flat), nu_flat);
  for (int i = 0; i < 3; ++i) {
    CHECK(nu[i] > 0.0);
    CHECK(nu_flat[i] == nu[i]);
  }
  // Quadratic in Delta.
  CHECK(nu[1] / nu[0] == doctest::Approx(4.0).epsilon(1e-14));

  SubgridViscosity none("none", {}, delta);
  CHECK(!none.active());
  none(generic, nu);
  for (double v : nu) CHECK(v == 0.0);
}

TEST_CASE("SubgridViscosity rejects bad input with a message") {
  CHECK_THROWS_WITH_AS(SubgridViscosity("sigma", {}, {1e-3, 0.0}), doctest::Contains("node 1"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(SubgridViscosity("vreman", {}, {1e-3}), doctest::Contains("vreman"),
                       std::invalid_argument);
  SubgridViscosity wale("wale", {}, {1e-3, 1e-3});
  CHECK(wale.model().constant == doctest::Approx(0.5));
  const std::vector<Eigen::Matrix3d> grad(3, Eigen::Matrix3d::Identity());
  std::vector<double> nu(3);
  CHECK_THROWS_AS(wale(grad, nu), std::invalid_argument);
}
