// The flow solver's adaptor les::SubgridViscosity: per-node filter widths, default constants,
// both gradient layouts, the update policy (per step or per RK stage), and clear errors.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "les/subgrid_viscosity.hpp"

using valsalva::les::SgsKind;
using valsalva::les::SubgridViscosity;

TEST_CASE("SubgridViscosity applies the model with each node's filter width") {
  // Pure shear du/dy = s: |S| = s, so Smagorinsky gives (C_s Delta)^2 s exactly.
  const double s = 40.0;
  Eigen::Matrix3d shear = Eigen::Matrix3d::Zero();
  shear(0, 1) = s;
  const std::vector<double> delta = {1e-3, 2e-3, 5e-4};
  const std::vector<Eigen::Matrix3d> grad(3, shear);
  std::vector<double> nu(3);
  SubgridViscosity smag(SgsKind::smagorinsky, {}, delta);
  CHECK(smag.active());
  CHECK(smag.model().constant == doctest::Approx(0.17));
  smag(grad, nu);
  for (int i = 0; i < 3; ++i)
    CHECK(nu[i] == doctest::Approx(std::pow(0.17 * delta[i], 2) * s).epsilon(1e-14));

  // Sigma vanishes for pure shear; a generic gradient gives the same value from the flat layout.
  SubgridViscosity sigma(SgsKind::sigma, 0.0, delta);  // 0 = default constant
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

  SubgridViscosity none(SgsKind::none, {}, delta);
  CHECK(!none.active());
  none(generic, nu);
  for (double v : nu) CHECK(v == 0.0);
}

TEST_CASE("SubgridViscosity rejects bad input with a message") {
  CHECK_THROWS_WITH_AS(SubgridViscosity(SgsKind::sigma, {}, {1e-3, 0.0}),
                       doctest::Contains("node 1"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(valsalva::les::parse_sgs_kind("vreman"), doctest::Contains("vreman"),
                       std::invalid_argument);
  SubgridViscosity wale(SgsKind::wale, {}, {1e-3, 1e-3});
  CHECK(wale.model().constant == doctest::Approx(0.5));
  const std::vector<Eigen::Matrix3d> grad(3, Eigen::Matrix3d::Identity());
  std::vector<double> nu(3);
  CHECK_THROWS_AS(wale(grad, nu), std::invalid_argument);
}

TEST_CASE("update policy: per step computes at stage 0 only and leaves nu_sgs alone after") {
  using valsalva::les::SgsUpdate;
  Eigen::Matrix3d g;
  g << 1.0, -2.0, 0.5, 3.0, 0.2, -1.1, 0.7, 1.9, -1.2;
  const std::vector<Eigen::Matrix3d> grad(2, g), other(2, 2.0 * g);
  const std::vector<double> delta = {1e-3, 2e-3};
  SubgridViscosity per_step(SgsKind::sigma, {}, delta, SgsUpdate::step);
  SubgridViscosity per_stage(SgsKind::sigma, {}, delta);  // the literal model is the class default
  CHECK(per_stage.update() == SgsUpdate::stage);
  std::vector<double> a(2), b(2);
  CHECK(per_step(0, grad, a));
  CHECK(per_stage(0, grad, b));
  CHECK(a == b);
  const std::vector<double> first = a;
  for (int stage = 1; stage < 4; ++stage) {
    CHECK_FALSE(per_step(stage, other, a));  // held: still the stage-0 values
    CHECK(a == first);
    CHECK(per_stage(stage, other, b));
  }
  // Sigma is homogeneous of degree 1 in g: the per-stage policy did recompute.
  CHECK(b[0] == doctest::Approx(2.0 * a[0]).epsilon(1e-14));
  CHECK(valsalva::les::parse_sgs_update("step") == SgsUpdate::step);
  CHECK(valsalva::les::parse_sgs_update("stage") == SgsUpdate::stage);
  CHECK_THROWS_WITH_AS(valsalva::les::parse_sgs_update("substep"),
                       doctest::Contains("is not one of stage, step"), std::invalid_argument);
}
