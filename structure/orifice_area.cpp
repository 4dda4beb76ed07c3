#include "structure/orifice_area.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace valsalva::structure {

namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double segment_distance(const Vec2& a, const Vec2& b) {  // from the origin
  const Vec2 d = b - a;
  const double t = std::clamp(-a.dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * d).norm();
}

// Polar grid over the disc; a cell is covered when its centre lies in a projected triangle.
class PolarRaster {
 public:
  PolarRaster(double radius, int rings, int sectors)
      : R_(radius),
        nr_(rings),
        ns_(sectors),
        h_(radius / rings),
        dth_(2 * M_PI / sectors),
        covered_(std::size_t(rings) * std::size_t(sectors), 0),
        cos_(sectors),
        sin_(sectors) {
    for (int j = 0; j < ns_; ++j)
      cos_[j] = std::cos((j + 0.5) * dth_), sin_[j] = std::sin((j + 0.5) * dth_);
  }

  void cover(const Vec2& a, const Vec2& b, const Vec2& c) {
    const double orient = cross(b - a, c - a);
    const double scale = std::max({a.squaredNorm(), b.squaredNorm(), c.squaredNorm(), R_ * R_});
    if (std::abs(orient) <= 1e-14 * scale) return;  // edge-on: covers no area
    const double s = orient > 0 ? 1.0 : -1.0;
    auto inside = [&](const Vec2& p) {
      return s * cross(b - a, p - a) >= 0 && s * cross(c - b, p - b) >= 0 &&
             s * cross(a - c, p - c) >= 0;
    };
    const bool origin_in = inside(Vec2::Zero());
    const double rmin =
        origin_in
            ? 0.0
            : std::min({segment_distance(a, b), segment_distance(b, c), segment_distance(c, a)});
    if (rmin >= R_) return;
    const double rmax = std::max({a.norm(), b.norm(), c.norm()});
    const int i0 = std::max(0, int(rmin / h_) - 1), i1 = std::min(nr_ - 1, int(rmax / h_) + 1);
    // Sector range: a triangle that does not contain the origin subtends less than pi, between
    // its extreme vertex angles.
    int j0 = 0, j1 = ns_ - 1;
    if (!origin_in) {
      const double t0 = std::atan2(a.y(), a.x());
      const double d1 = std::remainder(std::atan2(b.y(), b.x()) - t0, 2 * M_PI);
      const double d2 = std::remainder(std::atan2(c.y(), c.x()) - t0, 2 * M_PI);
      j0 = int(std::floor((t0 + std::min({0.0, d1, d2})) / dth_)) - 1;
      j1 = int(std::floor((t0 + std::max({0.0, d1, d2})) / dth_)) + 1;
      if (j1 - j0 >= ns_) j0 = 0, j1 = ns_ - 1;
    }
    for (int i = i0; i <= i1; ++i) {
      const double r = (i + 0.5) * h_;
      unsigned char* ring = covered_.data() + std::size_t(i) * ns_;
      for (int jj = j0; jj <= j1; ++jj) {
        const int j = ((jj % ns_) + ns_) % ns_;
        if (!ring[j] && inside(Vec2(r * cos_[j], r * sin_[j]))) ring[j] = 1;
      }
    }
  }

  void finish(OrificeArea& out, bool list_uncovered) const {
    auto cell_area = [&](int i) { return 0.5 * h_ * h_ * (2 * i + 1) * dth_; };
    std::vector<unsigned char> outline(covered_.size(), 0);
    auto at = [&](int i, int j) { return std::size_t(i) * ns_ + j; };
    for (int i = 0; i < nr_; ++i)
      for (int j = 0; j < ns_; ++j) {
        const int jn = (j + 1) % ns_;
        if (covered_[at(i, j)] != covered_[at(i, jn)]) outline[at(i, j)] = outline[at(i, jn)] = 1;
        if (i + 1 < nr_ && covered_[at(i, j)] != covered_[at(i + 1, j)])
          outline[at(i, j)] = outline[at(i + 1, j)] = 1;
      }
    double open = 0, edge = 0;
    for (int i = 0; i < nr_; ++i) {
      long n_open = 0, n_edge = 0;
      for (int j = 0; j < ns_; ++j) {
        n_open += !covered_[at(i, j)], n_edge += outline[at(i, j)];
        if (list_uncovered && !covered_[at(i, j)]) {
          const double r = (i + 0.5) * h_;
          out.uncovered.push_back({Vec2(r * cos_[j], r * sin_[j]), cell_area(i)});
        }
      }
      open += double(n_open) * cell_area(i);
      edge += double(n_edge) * cell_area(i);
    }
    out.area = open;
    out.raster_error = 0.5 * edge;
  }

 private:
  double R_;
  int nr_, ns_;
  double h_, dth_;
  std::vector<unsigned char> covered_;
  std::vector<double> cos_, sin_;
};

// Faces (element, local face) that belong to one element only.
std::vector<FaceRef> boundary_faces(const SolidMesh& m) {
  std::map<std::vector<int>, std::pair<FaceRef, int>> faces;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int f = 0; f < 6; ++f) {
      std::vector<int> key;
      for (int a : hex_face_nodes(m.order, f)) key.push_back(m.element_nodes(e)[a]);
      std::sort(key.begin(), key.end());
      auto [it, fresh] = faces.try_emplace(std::move(key), FaceRef{e, f}, 0);
      ++it->second.second;
    }
  std::vector<FaceRef> out;
  for (const auto& [key, v] : faces)
    if (v.second == 1) out.push_back(v.first);
  return out;
}

void check_leaflet(const LeafletPositions& l, std::size_t i) {
  if (!l.mesh || !l.x)
    throw std::invalid_argument(
        fmt::format("orifice area: leaflet {} has no mesh or positions", i));
  if (l.x->cols() != l.mesh->num_nodes())
    throw std::invalid_argument(
        fmt::format("orifice area: leaflet {} ({}) has {} positions for {} nodes", i,
                    l.mesh->source, l.x->cols(), l.mesh->num_nodes()));
  if (!l.x->allFinite())
    throw std::invalid_argument(
        fmt::format("orifice area: leaflet {} ({}) has non-finite positions", i, l.mesh->source));
}

}  // namespace

OrificeArea geometric_orifice_area(std::span<const LeafletPositions> leaflets,
                                   const ValveFrame& valve, const OrificeOptions& o) {
  const ValveBasis basis = valve_basis(valve);
  if (leaflets.empty()) throw std::invalid_argument("orifice area: no leaflets");
  if (o.rings < 1 || o.sectors < 0 || o.face_subdivision < 1)
    throw std::invalid_argument(
        fmt::format("orifice area: rings = {} and face_subdivision = {} must be >= 1, sectors = "
                    "{} >= 0 (0: automatic)",
                    o.rings, o.face_subdivision, o.sectors));
  const int sectors = o.sectors > 0 ? o.sectors : std::max(3, int(std::lround(2 * M_PI * o.rings)));
  if (double(o.rings) * sectors > 4e8)
    throw std::invalid_argument(
        fmt::format("orifice area: {} x {} grid cells is too many", o.rings, sectors));
  for (std::size_t i = 0; i < leaflets.size(); ++i) check_leaflet(leaflets[i], i);

  const double R = valve.annulus_radius;
  PolarRaster raster(R, o.rings, sectors);
  OrificeArea out;
  const int n = o.face_subdivision;
  for (const LeafletPositions& l : leaflets) {
    const SolidMesh& m = *l.mesh;
    const int nen = m.nodes_per_element();
    std::vector<double> N(nen), dN(3 * nen);
    std::vector<Vec2> p((n + 1) * (n + 1));
    for (const FaceRef& f : boundary_faces(m)) {
      const HexFace hf = hex_face(f.face);
      const int u = hf.axis == 0 ? 1 : 0, v = hf.axis == 2 ? 1 : 2;
      const int* en = m.element_nodes(f.element);
      for (int b = 0; b <= n; ++b)
        for (int a = 0; a <= n; ++a) {
          Vec3 xi;
          xi[hf.axis] = hf.side;
          xi[u] = -1 + 2.0 * a / n, xi[v] = -1 + 2.0 * b / n;
          hex_shape(m.order, xi, N, dN);
          Vec3 x = Vec3::Zero();
          for (int k = 0; k < nen; ++k) x += N[k] * l.x->col(en[k]);
          p[b * (n + 1) + a] = basis.to_local(x).head<2>();
        }
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
          const Vec2 &p00 = p[b * (n + 1) + a], &p10 = p[b * (n + 1) + a + 1],
                     &p01 = p[(b + 1) * (n + 1) + a], &p11 = p[(b + 1) * (n + 1) + a + 1];
          raster.cover(p00, p10, p11);
          raster.cover(p00, p11, p01);
          out.triangles += 2;
        }
    }
  }
  raster.finish(out, o.list_uncovered);
  out.disc_area = M_PI * R * R;
  out.opening_ratio = out.area / out.disc_area;
  out.rings = o.rings;
  out.sectors = sectors;
  return out;
}

}  // namespace valsalva::structure
