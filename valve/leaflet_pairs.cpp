#include "valve/leaflet_pairs.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "valve/mid_surface.hpp"

namespace valsalva::valve {

namespace {

using Box = Eigen::AlignedBox3d;

std::vector<Box> triangle_boxes(const TriangleSurface& s) {
  std::vector<Box> boxes;
  boxes.reserve(s.triangles.size());
  for (const auto& t : s.triangles) {
    Box b(s.points[t[0]]);
    b.extend(s.points[t[1]]);
    b.extend(s.points[t[2]]);
    boxes.push_back(b);
  }
  return boxes;
}

long count_crossings(const TriangleSurface& s, const std::vector<Box>& sb, const TriangleSurface& t,
                     const std::vector<Box>& tb, Vec3& mean) {
  long n = 0;
  mean.setZero();
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    for (std::size_t j = 0; j < t.triangles.size(); ++j) {
      if (!sb[i].intersects(tb[j])) continue;
      const auto& a = s.triangles[i];
      const auto& b = t.triangles[j];
      if (triangles_intersect({s.points[a[0]], s.points[a[1]], s.points[a[2]]},
                              {t.points[b[0]], t.points[b[1]], t.points[b[2]]})) {
        ++n;
        mean += (s.points[a[0]] + s.points[a[1]] + s.points[a[2]]) / 3;
      }
    }
  if (n) mean /= double(n);
  return n;
}

// Distance from each point of s to surface t.
std::vector<double> distances(const TriangleSurface& s, const TriangleSurface& t,
                              const std::vector<Box>& tb) {
  std::vector<double> d(s.points.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Vec3& p = s.points[i];
    for (std::size_t j = 0; j < t.triangles.size(); ++j) {
      if (tb[j].exteriorDistance(p) >= d[i]) continue;
      const auto& tr = t.triangles[j];
      const Vec3 c =
          closest_point_on_triangle(p, t.points[tr[0]], t.points[tr[1]], t.points[tr[2]]);
      d[i] = std::min(d[i], (p - c).norm());
    }
  }
  return d;
}

double axial_extent(const TriangleSurface& s, const std::vector<double>& d, double within,
                    const structure::ValveBasis& basis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (d[i] <= within) {
      const double z = basis.to_local(s.points[i]).z();
      lo = std::min(lo, z), hi = std::max(hi, z);
    }
  return hi >= lo ? hi - lo : 0.0;
}

// Mid-surfaces of the leaflets and the bounding boxes of their triangles.
struct MidSurfaces {
  std::vector<TriangleSurface> mids;
  std::vector<std::vector<Box>> boxes;
};

MidSurfaces mid_surfaces(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                         const std::vector<LeafletGroups>& leaflets) {
  MidSurfaces m;
  for (const auto& l : leaflets) {
    m.mids.push_back(mid_surface(mesh, x, l.aortic_face));
    m.boxes.push_back(triangle_boxes(m.mids.back()));
  }
  return m;
}

}  // namespace

bool leaflets_cross(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                    const std::vector<LeafletGroups>& leaflets) {
  const auto [mids, boxes] = mid_surfaces(mesh, x, leaflets);
  Vec3 unused;
  for (std::size_t a = 0; a < mids.size(); ++a)
    for (std::size_t b = a + 1; b < mids.size(); ++b)
      if (count_crossings(mids[a], boxes[a], mids[b], boxes[b], unused) > 0) return true;
  return false;
}

LeafletPairsReport leaflet_pairs(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                                 const std::vector<LeafletGroups>& leaflets,
                                 const structure::ValveFrame& valve, double coaptation_distance) {
  const structure::ValveBasis basis = structure::valve_basis(valve);
  const auto [mids, boxes] = mid_surfaces(mesh, x, leaflets);
  LeafletPairsReport r;
  r.min_distance = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(leaflets.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      LeafletPair p;
      p.a = a, p.b = b;
      p.crossings = count_crossings(mids[a], boxes[a], mids[b], boxes[b], p.crossing_at);
      if (p.crossings) p.crossing_at = basis.to_local(p.crossing_at);
      const auto dab = distances(mids[a], mids[b], boxes[b]);
      const auto dba = distances(mids[b], mids[a], boxes[a]);
      p.min_distance = std::min(*std::min_element(dab.begin(), dab.end()),
                                *std::min_element(dba.begin(), dba.end()));
      if (p.crossings > 0) p.min_distance = 0;  // they meet between the sample points
      p.coaptation_height = std::max(axial_extent(mids[a], dab, coaptation_distance, basis),
                                     axial_extent(mids[b], dba, coaptation_distance, basis));
      r.crossings += p.crossings;
      r.min_distance = std::min(r.min_distance, p.min_distance);
      r.coaptation_height = std::max(r.coaptation_height, p.coaptation_height);
      r.pairs.push_back(p);
    }
  return r;
}

}  // namespace valsalva::valve
