// Solid mesh of hexahedra (all Q1 or all Q2, Gmsh node order) in the reference configuration,
// with named node sets (Dirichlet supports, probes) and named surface sets (element faces for
// pressure and traction loads). Node coordinates are one contiguous 3 x n array.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "structure/hex_element.hpp"

namespace valsalva::structure {

struct FaceRef {
  int element;
  int face;  // local face 0..5, see hex_face()
};

struct SolidMesh {
  HexOrder order = HexOrder::q2;
  Eigen::Matrix3Xd X;             // reference node coordinates, one column per node
  std::vector<int> connectivity;  // nodes_per_element() entries per element
  std::map<std::string, std::vector<int>> node_sets;
  std::map<std::string, std::vector<FaceRef>> surface_sets;
  std::string source = "<generated>";

  int nodes_per_element() const { return hex_node_count(order); }
  int num_nodes() const { return static_cast<int>(X.cols()); }
  int num_elements() const { return static_cast<int>(connectivity.size()) / nodes_per_element(); }
  const int* element_nodes(int e) const { return connectivity.data() + e * nodes_per_element(); }

  const std::vector<int>& node_set(const std::string& name) const;
  const std::vector<FaceRef>& surface_set(const std::string& name) const;
  // Nodes on the faces of a surface set (sorted, unique).
  std::vector<int> surface_nodes(const std::string& name) const;

  // Throws, naming the element and Gauss point, if connectivity is out of range or an element
  // has a non-positive Jacobian (inverted or wrongly ordered) in the reference configuration.
  void validate() const;
};

}  // namespace valsalva::structure
