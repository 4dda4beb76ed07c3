// Cubed-sphere shell and enclosed volume; see sphere_shell.hpp.
#include "structure/sphere_shell.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "structure/mesh_generators.hpp"

namespace valsalva::structure {

SolidMesh sphere_shell(const SphereShell& s) {
  if (!(s.radius > s.thickness / 2 && s.thickness > 0 && s.n >= 1 && s.layers >= 1))
    throw std::invalid_argument(fmt::format(
        "sphere_shell: need radius > thickness/2 > 0, n >= 1, layers >= 1 (got R {} t {} n {} "
        "layers {})",
        s.radius, s.thickness, s.n, s.layers));
  SolidMesh out;
  out.order = HexOrder::q2;
  std::map<std::tuple<long, long, long>, int> index;  // merged nodes by rounded position
  std::vector<Vec3> nodes;
  const double quantum = 1e-9 * s.radius;
  auto node_id = [&](const Vec3& x) {
    const auto key = std::make_tuple(std::lround(x.x() / quantum), std::lround(x.y() / quantum),
                                     std::lround(x.z() / quantum));
    auto [it, fresh] = index.emplace(key, static_cast<int>(nodes.size()));
    if (fresh) nodes.push_back(x);
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {-1, 1}) {
      // Tangents (t1, t2) with t1 x t2 = outward normal, so that (u, v, w = radial) is
      // right-handed and the block's elements have positive Jacobians.
      const Vec3 normal = side * Vec3::Unit(axis);
      Vec3 t1 = Vec3::Unit((axis + 1) % 3), t2 = Vec3::Unit((axis + 2) % 3);
      if (side < 0) std::swap(t1, t2);
      const auto block = structured_block(HexOrder::q2, {s.n, s.n, s.layers}, [&](const Vec3& u) {
        const double a = std::tan(std::numbers::pi / 4 * (2 * u[0] - 1));
        const double b = std::tan(std::numbers::pi / 4 * (2 * u[1] - 1));
        const Vec3 p = (normal + a * t1 + b * t2).normalized();
        return Vec3(s.centre + (s.radius + (u[2] - 0.5) * s.thickness) * p);
      });
      const int first_element = out.num_elements();
      std::vector<int> local_to_merged(block.num_nodes());
      for (int a = 0; a < block.num_nodes(); ++a) local_to_merged[a] = node_id(block.X.col(a));
      for (int c : block.connectivity) out.connectivity.push_back(local_to_merged[c]);
      for (const auto& f : block.surface_set("w0"))
        out.surface_sets["inner"].push_back({first_element + f.element, f.face});
      for (const auto& f : block.surface_set("w1"))
        out.surface_sets["outer"].push_back({first_element + f.element, f.face});
    }
  out.X.resize(3, static_cast<int>(nodes.size()));
  for (std::size_t a = 0; a < nodes.size(); ++a) out.X.col(static_cast<int>(a)) = nodes[a];
  out.node_sets["inner"] = out.surface_nodes("inner");
  out.node_sets["outer"] = out.surface_nodes("outer");
  out.source = fmt::format("<cubed-sphere shell R={} t={} n={} layers={}>", s.radius, s.thickness,
                           s.n, s.layers);
  out.validate();
  return out;
}

double enclosed_volume(const SolidMesh& mesh, const Eigen::Matrix3Xd& x, const std::string& name) {
  const int nen = mesh.nodes_per_element();
  std::vector<double> N(nen), dN(3 * nen);
  double volume = 0;
  for (const auto& f : mesh.surface_set(name)) {
    const auto face = hex_face(f.face);
    const int a1 = (face.axis + 1) % 3, a2 = (face.axis + 2) % 3;
    const auto rule = gauss_face(f.face, 3);
    const int* en = mesh.element_nodes(f.element);
    for (int g = 0; g < rule.size(); ++g) {
      hex_shape(mesh.order, rule.points[g], N, dN);
      Vec3 p = Vec3::Zero(), d1 = Vec3::Zero(), d2 = Vec3::Zero();
      for (int a = 0; a < nen; ++a) {
        p += N[a] * x.col(en[a]);
        d1 += dN[3 * a + a1] * x.col(en[a]);
        d2 += dN[3 * a + a2] * x.col(en[a]);
      }
      // d1 x d2 points along +axis; the element's outward normal is side times that.
      volume += rule.weights[g] * face.side * p.dot(d1.cross(d2)) / 3;
    }
  }
  return std::abs(volume);
}

}  // namespace valsalva::structure
