// Base kernels (properties, not magic numbers: Peskin 2002 and Roma et al. 1999 list the sums
// each must satisfy) and the RKPM correction on random node clouds (the bucket grid, core's spatial
// index: tests/core/test_bucket_grid.cpp).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "ibm/kernels.hpp"
#include "ibm/rkpm.hpp"

using namespace valsalva;
using ibm::KernelType;

namespace {

// sum_j phi(r - j)^p (r - j)^q over the integers j.
double lattice_sum(KernelType type, double r, int q, int p = 1) {
  double s = 0;
  for (int j = -5; j <= 5; ++j) s += std::pow(ibm::kernel_1d(type, r - j), p) * std::pow(r - j, q);
  return s;
}

}  // namespace

TEST_CASE("base kernels: discrete moments, support and continuity") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (auto type : {KernelType::peskin4, KernelType::roma3, KernelType::bspline3}) {
    CAPTURE(ibm::kernel_name(type));
    const double w = ibm::natural_width(type);
    for (int t = 0; t < 50; ++t) {
      const double r = u(rng);
      CHECK(lattice_sum(type, r, 0) == doctest::Approx(1.0).epsilon(1e-14));
      // Roma's kernel and the B-spline also have zero first moment; Peskin's cosine does not.
      if (type != KernelType::peskin4) CHECK(std::abs(lattice_sum(type, r, 1)) < 1e-14);
      // Roma's second condition: sum phi^2 = 1/2 for every shift (Roma et al. 1999).
      if (type == KernelType::roma3) CHECK(lattice_sum(type, r, 0, 2) == doctest::Approx(0.5));
    }
    CHECK(ibm::kernel_1d(type, 0.5 * w) == doctest::Approx(0.0).scale(1.0).epsilon(1e-15));
    CHECK(ibm::kernel_1d(type, 0.5 * w + 1e-9) == 0.0);
    CHECK(ibm::kernel_1d(type, -0.3) == ibm::kernel_1d(type, 0.3));
    for (double b : {0.5, 1.0, 1.5}) {  // the breakpoints of the piecewise formulas
      CAPTURE(b);
      CHECK(std::abs(ibm::kernel_1d(type, b - 1e-12) - ibm::kernel_1d(type, b + 1e-12)) < 1e-9);
    }
    // psi integrates to one for any width and h (midpoint rule on a fine grid: the kernels are
    // C0 with kinks at grid breakpoints, so the error is O(dx^2)).
    ibm::KernelShape shape{type, 5.0};
    const double h = 0.01, a = ibm::support_radius(shape, h);
    const int n = 60;
    const double dx = 2 * a / n;
    double integral = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          integral += ibm::kernel_3d(
              shape, Eigen::Vector3d(-a + (i + 0.5) * dx, -a + (j + 0.5) * dx, -a + (k + 0.5) * dx),
              h);
    CHECK(integral * dx * dx * dx == doctest::Approx(1.0).epsilon(2e-3));
    CHECK(ibm::kernel_3d(shape, Eigen::Vector3d(a * 1.0001, 0, 0), h) == 0.0);
  }
  CHECK(ibm::parse_kernel_type("roma3") == KernelType::roma3);
  CHECK_THROWS_WITH_AS(ibm::parse_kernel_type("gauss"), doctest::Contains("'gauss'"),
                       std::invalid_argument);
}

TEST_CASE("RKPM correction restores partition of unity and zero first moment") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), vol(0.5, 1.5);
  const double h = 0.02;
  const ibm::KernelShape shape{KernelType::peskin4, 4.0};
  for (bool cut : {false, true}) {  // cut: the support clipped by a wall at y1 = 0.3 h
    CAPTURE(cut);
    std::vector<Eigen::Vector3d> y;
    std::vector<double> psi, v;
    for (int j = 0; j < 400; ++j) {
      Eigen::Vector3d p(u(rng), u(rng), u(rng));
      p *= 2 * h;
      if (cut && p.x() < -0.3 * h) continue;
      y.push_back(p);
      psi.push_back(ibm::kernel_3d(shape, p, h));
      v.push_back(vol(rng) * h * h * h / 8);
    }
    std::vector<double> phi(y.size());
    const auto r = ibm::rkpm_correct(y, psi, v, 2 * h, 1e-6, phi);
    REQUIRE(r.ok);
    double zeroth = 0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    for (std::size_t j = 0; j < y.size(); ++j) {
      zeroth += phi[j] * v[j];
      first += y[j] * phi[j] * v[j];
    }
    CHECK(std::abs(zeroth - 1) < 1e-13);
    CHECK(first.norm() / h < 1e-13);
  }
  // Coplanar nodes: M is singular in the normal direction, and the correction says so.
  std::vector<Eigen::Vector3d> y;
  std::vector<double> psi, v;
  for (int j = 0; j < 50; ++j) {
    y.emplace_back(0.0, u(rng) * h, u(rng) * h);
    psi.push_back(ibm::kernel_3d(shape, y.back(), h));
    v.push_back(h * h * h);
  }
  std::vector<double> phi(y.size());
  const auto r = ibm::rkpm_correct(y, psi, v, 2 * h, 1e-6, phi);
  CHECK_FALSE(r.ok);
  CHECK(r.rcond < 1e-12);
}
