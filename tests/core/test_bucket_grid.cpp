// The one spatial index (core/bucket_grid.hpp): box and nearest-point queries agree with brute
// force on random clouds, including a flat cloud (a periodic patch), duplicate points (ties go
// to the lower index) and a bucket size far below the point spacing (the grid widens it).
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/bucket_grid.hpp"

using valsalva::core::BucketGrid;

namespace {

std::vector<int> brute_in_box(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& x,
                              double radius) {
  std::vector<int> expected;
  for (int n = 0; n < static_cast<int>(points.size()); ++n)
    if ((points[n] - x).cwiseAbs().maxCoeff() <= radius) expected.push_back(n);
  return expected;
}

template <class Accept>
BucketGrid::Nearest brute_nearest(const std::vector<Eigen::Vector3d>& points,
                                  const Eigen::Vector3d& x, double max_distance, Accept accept) {
  BucketGrid::Nearest best;
  for (int n = 0; n < static_cast<int>(points.size()); ++n) {
    if (!accept(n)) continue;
    const double d = (points[n] - x).norm();
    if (d <= max_distance && d < best.distance) best = {n, d};  // first (lowest) index wins ties
  }
  return best;
}

// Random queries in and around the cloud's box [0, extent].
void compare_with_brute_force(const std::vector<Eigen::Vector3d>& points, double cell,
                              const Eigen::Vector3d& extent, std::mt19937_64& rng) {
  const BucketGrid grid(points, cell);
  CHECK(grid.size() == points.size());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<int> found;
  const double scale = extent.maxCoeff();
  for (int t = 0; t < 300; ++t) {
    Eigen::Vector3d x;
    for (int d = 0; d < 3; ++d) x[d] = (1.4 * u(rng) - 0.2) * extent[d];
    if (t % 5 == 0) x = points[t % points.size()];  // exactly on a point
    const double radius = scale * (0.005 + 0.1 * u(rng));
    grid.in_box(x, radius, found);
    std::sort(found.begin(), found.end());
    CHECK(found == brute_in_box(points, x, radius));

    const double reach = scale * (t % 3 == 0 ? 0.02 : 0.4);
    auto every_third = [](int n) { return n % 3 != 1; };
    const auto near = grid.nearest(x, reach, every_third);
    const auto expected = brute_nearest(points, x, reach, every_third);
    CHECK(near.index == expected.index);
    if (expected.index >= 0) CHECK(near.distance == expected.distance);
    const auto any = grid.nearest(x, reach, [](int) { return true; });
    CHECK(any.index == brute_nearest(points, x, reach, [](int) { return true; }).index);
  }
}

}  // namespace

TEST_CASE("bucket grid agrees with brute force on a random cloud") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(3000);
  for (auto& p : points) p = Eigen::Vector3d(u(rng), 0.5 * u(rng), 0.3 * u(rng));
  for (double cell : {0.05, 0.013, 0.4, 2.0}) {
    CAPTURE(cell);
    compare_with_brute_force(points, cell, Eigen::Vector3d(1.0, 0.5, 0.3), rng);
  }
}

TEST_CASE("bucket grid on a flat cloud with duplicate points: ties go to the lower index") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(800);
  for (auto& p : points) p = Eigen::Vector3d(u(rng), u(rng), 0.25);
  for (int n = 0; n < 100; ++n) points[400 + n] = points[n];  // duplicates at higher indices
  compare_with_brute_force(points, 0.03, Eigen::Vector3d(1.0, 1.0, 0.5), rng);
  const BucketGrid grid(points, 0.03);
  for (int n = 0; n < 100; ++n) {
    const auto near = grid.nearest(points[400 + n], 1e-12, [](int) { return true; });
    CHECK(near.index == n);
    CHECK(near.distance == 0.0);
  }
}

TEST_CASE("a bucket size far below the spacing is widened, and results do not change") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(500);
  for (auto& p : points) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
  const BucketGrid grid(points, 1e-12);  // 1e36 buckets if taken literally
  CHECK(grid.cell_size() > 1e-3);
  compare_with_brute_force(points, 1e-12, Eigen::Vector3d(1.0, 1.0, 1.0), rng);
  // A matching tolerance query (the periodic use): the point itself, nothing else.
  for (int n = 0; n < 50; ++n) {
    const Eigen::Vector3d target = points[n] + Eigen::Vector3d::Constant(1e-14);
    CHECK(grid.nearest(target, 1e-12, [](int) { return true; }).index == n);
  }
}

TEST_CASE("bucket grid edge cases") {
  const std::vector<Eigen::Vector3d> none;
  const BucketGrid empty(none, 1.0);
  std::vector<int> found{1, 2};
  empty.in_box(Eigen::Vector3d::Zero(), 10.0, found);
  CHECK(found.empty());
  CHECK(empty.nearest(Eigen::Vector3d::Zero(), 10.0, [](int) { return true; }).index == -1);

  const std::vector<Eigen::Vector3d> one{Eigen::Vector3d(1, 2, 3)};
  const BucketGrid single(one, 0.1);
  single.in_box(Eigen::Vector3d(1, 2, 3.05), 0.05, found);
  CHECK(found == std::vector<int>{0});
  CHECK(single.nearest(Eigen::Vector3d(5, 5, 5), 1.0, [](int) { return true; }).index == -1);
  CHECK(single.nearest(Eigen::Vector3d(1, 2, 4), 1.0, [](int) { return true; }).index == 0);
  CHECK(single.nearest(Eigen::Vector3d(1, 2, 4), 1.0, [](int) { return false; }).index == -1);

  CHECK_THROWS_AS(BucketGrid(one, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(BucketGrid(one, -1.0), std::invalid_argument);
}
