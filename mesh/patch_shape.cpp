#include "mesh/patch_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesh/mesh_check.hpp"

namespace valsalva::mesh {

PatchShape patch_shape(const mesh::Mesh& mesh, int patch) {
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double total = 0;
  for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.face_patches[f] != patch) continue;
    const auto nodes = mesh.face(f);
    const Eigen::Vector3d a = mesh::face_area(mesh, nodes);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (auto n : nodes) centre += mesh.nodes[n];
    centre /= static_cast<double>(nodes.size());
    area_vector += a;
    moment += a.norm() * centre;
    total += a.norm();
  }
  PatchShape s;
  s.area = area_vector.norm();
  s.circularity = std::numeric_limits<double>::infinity();  // no faces, or a closed surface
  if (!(total > 0) || !(s.area > 1e-9 * total)) return s;
  const Eigen::Vector3d centroid = moment / total, normal = area_vector / s.area;
  for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f)
    if (mesh.face_patches[f] == patch)
      for (auto n : mesh.face(f)) {
        const Eigen::Vector3d d = mesh.nodes[n] - centroid;
        s.max_radius = std::max(s.max_radius, (d - d.dot(normal) * normal).norm());
      }
  s.circularity = s.max_radius / std::sqrt(s.area / std::numbers::pi);
  return s;
}

}  // namespace valsalva::mesh
