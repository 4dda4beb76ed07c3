// Lagrange hexahedra on the reference cube [-1,1]^3: Q1 (8 nodes) and Q2 (27 nodes), nodes in
// Gmsh order (Gmsh reference manual, "Node ordering": vertices, then the 12 edges, then the 6
// faces, then the centre). Shape functions are tensor products of 1D Lagrange polynomials on
// {-1, 1} (Q1) or {-1, 0, 1} (Q2). Gauss–Legendre rules of 1..4 points per direction.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "structure/tensor.hpp"

namespace valsalva::structure {

enum class HexOrder { q1 = 1, q2 = 2 };

int hex_node_count(HexOrder order);  // 8 or 27

// Reference coordinates of local node a (each component in {-1, 0, 1}).
Vec3 hex_reference_node(HexOrder order, int a);

// Values N_a(xi) and reference derivatives dN_a/dxi_k, written into spans of nen / 3*nen.
void hex_shape(HexOrder order, const Vec3& xi, std::span<double> N, std::span<double> dN);

// Local faces in Gmsh order: 0: zeta=-1, 1: eta=-1, 2: xi=-1, 3: xi=+1, 4: eta=+1, 5: zeta=+1.
// axis is the fixed reference coordinate, side its value (-1 or +1).
struct HexFace {
  int axis;
  int side;
};
HexFace hex_face(int face);
// Local nodes lying on a face (4 for Q1, 9 for Q2).
std::vector<int> hex_face_nodes(HexOrder order, int face);

// Tensor-product Gauss rule, n[k] points along reference direction k.
struct QuadratureRule {
  std::vector<Vec3> points;
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
};
QuadratureRule gauss_hex(std::array<int, 3> n);
// Rule on a face: points in 3D reference coordinates (fixed axis at its side), 2D weights.
QuadratureRule gauss_face(int face, int n);
// Default full rules: 2x2x2 for Q1, 3x3x3 for Q2 (exact for the reference mass matrix).
std::array<int, 3> default_gauss(HexOrder order);

}  // namespace valsalva::structure
