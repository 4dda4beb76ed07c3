#include "structure/solid_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace valsalva::structure {

const std::vector<int>& SolidMesh::node_set(const std::string& name) const {
  auto it = node_sets.find(name);
  if (it == node_sets.end()) {
    std::string known;
    for (const auto& [k, v] : node_sets) known += " " + k;
    throw std::invalid_argument(
        fmt::format("solid mesh {}: no node set '{}' (known:{})", source, name, known));
  }
  return it->second;
}

const std::vector<FaceRef>& SolidMesh::surface_set(const std::string& name) const {
  auto it = surface_sets.find(name);
  if (it == surface_sets.end()) {
    std::string known;
    for (const auto& [k, v] : surface_sets) known += " " + k;
    throw std::invalid_argument(
        fmt::format("solid mesh {}: no surface set '{}' (known:{})", source, name, known));
  }
  return it->second;
}

std::vector<int> SolidMesh::surface_nodes(const std::string& name) const {
  std::vector<int> out;
  for (const FaceRef& f : surface_set(name))
    for (int a : hex_face_nodes(order, f.face)) out.push_back(element_nodes(f.element)[a]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void SolidMesh::validate() const {
  const int nen = nodes_per_element();
  if (connectivity.size() % nen != 0)
    throw std::runtime_error(
        fmt::format("solid mesh {}: connectivity size {} is not a multiple of {}", source,
                    connectivity.size(), nen));
  for (std::size_t i = 0; i < connectivity.size(); ++i)
    if (connectivity[i] < 0 || connectivity[i] >= num_nodes())
      throw std::runtime_error(
          fmt::format("solid mesh {}: element {} refers to node {} (mesh has {})", source, i / nen,
                      connectivity[i], num_nodes()));
  const QuadratureRule q = gauss_hex(default_gauss(order));
  std::vector<double> N(nen), dN(3 * nen);
  for (int e = 0; e < num_elements(); ++e) {
    const int* en = element_nodes(e);
    for (int g = 0; g < q.size(); ++g) {
      hex_shape(order, q.points[g], N, dN);
      Mat3 J = Mat3::Zero();
      for (int a = 0; a < nen; ++a)
        for (int k = 0; k < 3; ++k) J.col(k) += X.col(en[a]) * dN[3 * a + k];
      if (!(J.determinant() > 0))
        throw std::runtime_error(fmt::format(
            "solid mesh {}: element {} has Jacobian determinant {:.3e} at Gauss point {} "
            "(inverted element or wrong node order)",
            source, e, J.determinant(), g));
    }
  }
  for (const auto& [name, faces] : surface_sets)
    for (const FaceRef& f : faces)
      if (f.element < 0 || f.element >= num_elements() || f.face < 0 || f.face > 5)
        throw std::runtime_error(
            fmt::format("solid mesh {}: surface set '{}' has face ({}, {}) out of range", source,
                        name, f.element, f.face));
  for (const auto& [name, nodes] : node_sets)
    for (int n : nodes)
      if (n < 0 || n >= num_nodes())
        throw std::runtime_error(
            fmt::format("solid mesh {}: node set '{}' has node {} out of range", source, name, n));
}

}  // namespace valsalva::structure
