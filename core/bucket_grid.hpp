// The spatial index of the tree: a uniform bucket grid over a fixed point cloud, with buckets
// about one mesh size wide. Finding the points in a box visits only the buckets the box overlaps;
// the nearest point is found by growing rings of buckets. Users: the immersed boundary (a rank's
// fluid nodes near a marker; the nodes do not move, built once), contact search (master face
// centres, rebuilt per evaluation), periodic node matching (master patch nodes) and the point
// locator (cell box centres, one grid per cell size class).
// The grid holds a view of the points: they must outlive it and not move.
// A requested bucket size far below the point spacing (a matching tolerance, say) is widened
// until the grid has at most max(64 n, 4096) buckets, so memory stays O(n) whatever the size asked
// (a safety net: at mesh-size buckets it does not act).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace valsalva::core {

class BucketGrid {
 public:
  BucketGrid() = default;
  // `cell_size` > 0: side of a bucket (the typical mesh size is a good choice); widened (doubled)
  // while the grid would have more than max(64 n, 4096) buckets.
  BucketGrid(std::span<const Eigen::Vector3d> points, double cell_size);

  // Indices of the points with |x_j - centre|_inf <= radius, appended to `out` (cleared first),
  // in bucket order (not sorted).
  void in_box(const Eigen::Vector3d& centre, double radius, std::vector<int>& out) const;

  struct Nearest {
    int index = -1;  // -1: no accepted point in the cloud
    double distance = std::numeric_limits<double>::infinity();
  };
  // Nearest point (Euclidean) within `max_distance` of x among those with accept(index) true;
  // ties go to the lower index.
  template <class Accept>
  Nearest nearest(const Eigen::Vector3d& x, double max_distance, Accept accept) const;

  std::size_t size() const { return points_.size(); }
  double cell_size() const { return cell_; }  // after any widening

 private:
  std::array<int, 3> cell_of(const Eigen::Vector3d& x) const;  // clamped to the grid
  int flat(int i, int j, int k) const { return (k * dims_[1] + j) * dims_[0] + i; }

  std::span<const Eigen::Vector3d> points_;
  Eigen::Vector3d lower_ = Eigen::Vector3d::Zero();
  double cell_ = 1.0;
  std::array<int, 3> dims_{0, 0, 0};
  std::vector<int> start_;  // CSR: bucket b holds index_[start_[b] .. start_[b + 1])
  std::vector<int> index_;
};

template <class Accept>
BucketGrid::Nearest BucketGrid::nearest(const Eigen::Vector3d& x, double max_distance,
                                        Accept accept) const {
  Nearest best;
  if (points_.empty()) return best;
  const Eigen::Vector3d upper = lower_ + cell_ * Eigen::Vector3d(dims_[0], dims_[1], dims_[2]);
  if ((x.cwiseMax(lower_).cwiseMin(upper) - x).norm() > max_distance) return best;
  const auto c = cell_of(x);
  const int max_ring = static_cast<int>(std::ceil(max_distance / cell_)) + 1;
  for (int ring = 0; ring <= max_ring; ++ring) {
    // x lies in (or, clamped, beyond) bucket c, so every point of ring r is at least
    // (r - 1) * cell away: stop once that exceeds the best distance found.
    if (best.index >= 0 && (ring - 1) * cell_ > best.distance) break;
    for (int k = std::max(c[2] - ring, 0); k <= std::min(c[2] + ring, dims_[2] - 1); ++k) {
      for (int j = std::max(c[1] - ring, 0); j <= std::min(c[1] + ring, dims_[1] - 1); ++j) {
        const bool face = std::abs(k - c[2]) == ring || std::abs(j - c[1]) == ring;
        const int step = face || ring == 0 ? 1 : 2 * ring;  // interior rows: only the two ends
        for (int i = c[0] - ring; i <= c[0] + ring; i += step) {
          if (i < 0 || i >= dims_[0]) continue;
          const int b = flat(i, j, k);
          for (int p = start_[b]; p < start_[b + 1]; ++p) {
            const int n = index_[p];
            if (!accept(n)) continue;
            const double d = (points_[n] - x).norm();
            if (d < best.distance || (d == best.distance && n < best.index)) best = {n, d};
          }
        }
      }
    }
  }
  if (best.distance > max_distance) best = {};
  return best;
}

}  // namespace valsalva::core
