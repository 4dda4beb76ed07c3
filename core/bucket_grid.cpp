#include "core/bucket_grid.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace valsalva::core {

BucketGrid::BucketGrid(std::span<const Eigen::Vector3d> points, double cell_size)
    : points_(points), cell_(cell_size) {
  if (!(cell_size > 0) || !std::isfinite(cell_size))
    throw std::invalid_argument(
        fmt::format("BucketGrid: cell size {} must be finite and > 0", cell_size));
  if (points.empty()) return;
  lower_ = points[0];
  Eigen::Vector3d upper = points[0];
  for (const auto& p : points) {
    lower_ = lower_.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  const double max_buckets = std::max(64.0 * static_cast<double>(points.size()), 4096.0);
  auto count = [&](int d) { return std::floor((upper[d] - lower_[d]) / cell_) + 1; };
  while (count(0) * count(1) * count(2) > max_buckets) cell_ *= 2;
  for (int d = 0; d < 3; ++d) dims_[d] = std::max(1, static_cast<int>(count(d)));
  const std::size_t buckets = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  start_.assign(buckets + 1, 0);
  std::vector<int> bucket(points.size());
  for (std::size_t n = 0; n < points.size(); ++n) {
    const auto c = cell_of(points[n]);
    bucket[n] = flat(c[0], c[1], c[2]);
    ++start_[bucket[n] + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
  index_.resize(points.size());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t n = 0; n < points.size(); ++n) index_[fill[bucket[n]]++] = static_cast<int>(n);
}

std::array<int, 3> BucketGrid::cell_of(const Eigen::Vector3d& x) const {
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d) {
    const double t = std::floor((x[d] - lower_[d]) / cell_);
    c[d] = static_cast<int>(std::clamp(t, 0.0, static_cast<double>(dims_[d] - 1)));
  }
  return c;
}

void BucketGrid::in_box(const Eigen::Vector3d& centre, double radius, std::vector<int>& out) const {
  out.clear();
  if (points_.empty()) return;
  // A box beyond the grid would be clamped onto its boundary buckets and scan them for nothing
  // (periodic images of a support mostly lie outside).
  const Eigen::Vector3d upper = lower_ + cell_ * Eigen::Vector3d(dims_[0], dims_[1], dims_[2]);
  if (((centre.array() + radius) < lower_.array()).any() ||
      ((centre.array() - radius) > upper.array()).any())
    return;
  const auto lo = cell_of(centre - Eigen::Vector3d::Constant(radius));
  const auto hi = cell_of(centre + Eigen::Vector3d::Constant(radius));
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const int b = flat(i, j, k);
        for (int p = start_[b]; p < start_[b + 1]; ++p) {
          const int n = index_[p];
          if ((points_[n] - centre).cwiseAbs().maxCoeff() <= radius) out.push_back(n);
        }
      }
}

}  // namespace valsalva::core
