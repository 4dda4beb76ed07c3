#include "valve/mid_surface.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace valsalva::valve {

TriangleSurface mid_surface(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                            const std::string& face_set, int n) {
  if (x.cols() != mesh.num_nodes())
    throw std::invalid_argument(
        fmt::format("{}: {} positions for {} nodes", mesh.source, x.cols(), mesh.num_nodes()));
  if (n < 1) throw std::invalid_argument("mid_surface: subdivision below 1");
  const int nen = mesh.nodes_per_element();
  std::vector<double> N(nen), dN(3 * nen);
  TriangleSurface s;
  for (const auto& f : mesh.surface_set(face_set)) {
    const structure::HexFace hf = structure::hex_face(f.face);
    const int u = (hf.axis + 1) % 3, v = (hf.axis + 2) % 3;
    const int base = static_cast<int>(s.points.size());
    const int* en = mesh.element_nodes(f.element);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec3 xi = Vec3::Zero();  // the fixed axis at 0: half-way through the thickness
        xi[u] = -1 + 2.0 * i / n;
        xi[v] = -1 + 2.0 * j / n;
        structure::hex_shape(mesh.order, xi, N, dN);
        Vec3 p = Vec3::Zero();
        for (int a = 0; a < nen; ++a) p += N[a] * x.col(en[a]);
        s.points.push_back(p);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int p0 = base + j * (n + 1) + i, p1 = p0 + 1, p2 = p0 + n + 1, p3 = p2 + 1;
        s.triangles.push_back({p0, p1, p3});
        s.triangles.push_back({p0, p3, p2});
      }
  }
  return s;
}

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);
  const double scale = d.norm() * e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) return false;  // parallel or coplanar
  const double tol = 1e-12;
  const Vec3 s = p - a;
  const double u = s.dot(h) / det;
  if (u < -tol || u > 1 + tol) return false;
  const Vec3 qv = s.cross(e1);
  const double v = d.dot(qv) / det;
  if (v < -tol || u + v > 1 + tol) return false;
  const double t = e2.dot(qv) / det;
  return t >= -tol && t <= 1 + tol;
}

bool triangles_intersect(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t) {
  for (int k = 0; k < 3; ++k) {
    if (segment_crosses_triangle(s[k], s[(k + 1) % 3], t[0], t[1], t[2])) return true;
    if (segment_crosses_triangle(t[k], t[(k + 1) % 3], s[0], s[1], s[2])) return true;
  }
  return false;
}

}  // namespace valsalva::valve
