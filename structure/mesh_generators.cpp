#include "structure/mesh_generators.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace valsalva::structure {

namespace {
int face_id(int axis, int side) {
  static constexpr int ids[3][2] = {{2, 3}, {1, 4}, {0, 5}};
  return ids[axis][side > 0 ? 1 : 0];
}
}  // namespace

SolidMesh structured_block(HexOrder order, std::array<int, 3> n,
                           const std::function<Vec3(const Vec3&)>& map) {
  for (int k = 0; k < 3; ++k)
    if (n[k] < 1)
      throw std::invalid_argument(
          fmt::format("structured_block: {} elements along direction {}", n[k], k));
  const int p = static_cast<int>(order);
  const std::array<int, 3> m = {p * n[0] + 1, p * n[1] + 1, p * n[2] + 1};
  auto gid = [&](int i, int j, int k) { return i + m[0] * (j + m[1] * k); };

  SolidMesh mesh;
  mesh.order = order;
  mesh.X.resize(3, m[0] * m[1] * m[2]);
  for (int k = 0; k < m[2]; ++k)
    for (int j = 0; j < m[1]; ++j)
      for (int i = 0; i < m[0]; ++i)
        mesh.X.col(gid(i, j, k)) =
            map(Vec3(double(i) / (m[0] - 1), double(j) / (m[1] - 1), double(k) / (m[2] - 1)));

  const int nen = hex_node_count(order);
  static const char* names[3][2] = {{"u0", "u1"}, {"v0", "v1"}, {"w0", "w1"}};
  for (int ek = 0; ek < n[2]; ++ek)
    for (int ej = 0; ej < n[1]; ++ej)
      for (int ei = 0; ei < n[0]; ++ei) {
        const int e = mesh.num_elements();
        for (int a = 0; a < nen; ++a) {
          const Vec3 r = hex_reference_node(order, a);
          const int di = static_cast<int>((r[0] + 1) * p / 2),
                    dj = static_cast<int>((r[1] + 1) * p / 2),
                    dk = static_cast<int>((r[2] + 1) * p / 2);
          mesh.connectivity.push_back(gid(p * ei + di, p * ej + dj, p * ek + dk));
        }
        const int idx[3] = {ei, ej, ek};
        for (int axis = 0; axis < 3; ++axis) {
          if (idx[axis] == 0) mesh.surface_sets[names[axis][0]].push_back({e, face_id(axis, -1)});
          if (idx[axis] == n[axis] - 1)
            mesh.surface_sets[names[axis][1]].push_back({e, face_id(axis, 1)});
        }
      }
  for (int k = 0; k < m[2]; ++k)
    for (int j = 0; j < m[1]; ++j)
      for (int i = 0; i < m[0]; ++i) {
        const int idx[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis) {
          if (idx[axis] == 0) mesh.node_sets[names[axis][0]].push_back(gid(i, j, k));
          if (idx[axis] == m[axis] - 1) mesh.node_sets[names[axis][1]].push_back(gid(i, j, k));
        }
      }
  mesh.validate();
  return mesh;
}

void append_body(SolidMesh& mesh, const SolidMesh& body, const std::string& prefix) {
  if (mesh.num_nodes() == 0) mesh.order = body.order;
  if (mesh.order != body.order)
    throw std::invalid_argument("append_body: '" + prefix + "' has a different element order");
  const int n0 = mesh.num_nodes(), e0 = mesh.num_elements();
  mesh.X.conservativeResize(3, n0 + body.num_nodes());
  mesh.X.rightCols(body.num_nodes()) = body.X;
  for (int c : body.connectivity) mesh.connectivity.push_back(n0 + c);
  for (const auto& [name, nodes] : body.node_sets) {
    auto& set = mesh.node_sets[prefix + name];
    for (int n : nodes) set.push_back(n0 + n);
  }
  for (const auto& [name, faces] : body.surface_sets) {
    auto& set = mesh.surface_sets[prefix + name];
    for (const FaceRef& f : faces) set.push_back({e0 + f.element, f.face});
  }
}

void alias_sets(SolidMesh& mesh, const std::string& name, const std::string& alias) {
  mesh.node_sets[alias] = mesh.node_set(name);
  if (auto it = mesh.surface_sets.find(name); it != mesh.surface_sets.end())
    mesh.surface_sets[alias] = it->second;
}

SolidMesh cylindrical_shell_patch(HexOrder order, const ShellPatch& p) {
  if (!(p.radius > 0 && p.thickness > 0 && p.height > 0 && p.angle > 0 &&
        p.thickness < 2 * p.radius))
    throw std::invalid_argument(fmt::format(
        "cylindrical_shell_patch: need radius > 0, 0 < thickness < 2 radius, height > 0, angle > 0 "
        "(got radius {}, thickness {}, height {}, angle {})",
        p.radius, p.thickness, p.height, p.angle));
  SolidMesh mesh =
      structured_block(order, {p.n_angle, p.n_height, p.n_thickness}, [&](const Vec3& s) {
        const double th = (s[0] - 0.5) * p.angle;
        const double r = p.radius + (s[2] - 0.5) * p.thickness;
        return Vec3(r * std::cos(th), r * std::sin(th), s[1] * p.height);
      });
  mesh.source = fmt::format("<cylindrical shell patch R={} angle={} H={} t={}>", p.radius, p.angle,
                            p.height, p.thickness);
  alias_sets(mesh, "u0", "side0");
  alias_sets(mesh, "u1", "side1");
  alias_sets(mesh, "v0", "attachment");
  alias_sets(mesh, "v1", "free_edge");
  alias_sets(mesh, "w0", "inner");
  alias_sets(mesh, "w1", "outer");
  return mesh;
}

SolidMesh straight_bar(HexOrder order, const Bar& b) {
  if (!(b.length > 0 && b.height > 0 && b.depth > 0))
    throw std::invalid_argument(fmt::format(
        "straight_bar: sizes must be positive (got {} x {} x {})", b.length, b.height, b.depth));
  SolidMesh mesh = structured_block(order, {b.n_length, b.n_height, b.n_depth}, [&](const Vec3& s) {
    return Vec3(b.origin[0] + s[0] * b.length, b.origin[1] + s[1] * b.height,
                b.origin[2] + s[2] * b.depth);
  });
  mesh.source = fmt::format("<bar {} x {} x {}>", b.length, b.height, b.depth);
  alias_sets(mesh, "u0", "clamped");
  alias_sets(mesh, "u1", "tip");
  alias_sets(mesh, "v0", "bottom");
  alias_sets(mesh, "v1", "top");
  alias_sets(mesh, "w0", "back");
  alias_sets(mesh, "w1", "front");
  return mesh;
}

}  // namespace valsalva::structure
