#include "structure/hex_element.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace valsalva::structure {

namespace {

// Gmsh reference coordinates of the 27-node hexahedron (vertices 0..7 are the Q1 element,
// edges 8..19, faces 20..25, centre 26).
constexpr int kNodes[27][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1},  // vertices, bottom
    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},   {-1, 1, 1},   // vertices, top
    {0, -1, -1},  {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1},   // edges 0-1, 0-3, 0-4, 1-2
    {1, -1, 0},   {0, 1, -1},  {1, 1, 0},   {-1, 1, 0},   // edges 1-5, 2-3, 2-6, 3-7
    {0, -1, 1},   {-1, 0, 1},  {1, 0, 1},   {0, 1, 1},    // edges 4-5, 4-7, 5-6, 6-7
    {0, 0, -1},   {0, -1, 0},  {-1, 0, 0},  {1, 0, 0},    // faces z-, y-, x-, x+
    {0, 1, 0},    {0, 0, 1},   {0, 0, 0}};                // faces y+, z+, centre

// 1D Lagrange basis on {-1,1} (q1) or {-1,0,1} (q2), node value v in {-1,0,1}.
inline void lagrange1d(HexOrder order, int v, double x, double& L, double& dL) {
  if (order == HexOrder::q1) {
    L = 0.5 * (1.0 + v * x);
    dL = 0.5 * v;
    return;
  }
  switch (v) {
    case -1:
      L = 0.5 * x * (x - 1.0);
      dL = x - 0.5;
      break;
    case 0:
      L = 1.0 - x * x;
      dL = -2.0 * x;
      break;
    default:
      L = 0.5 * x * (x + 1.0);
      dL = x + 0.5;
      break;
  }
}

}  // namespace

int hex_node_count(HexOrder order) {
  return order == HexOrder::q1 ? 8 : 27;
}

Vec3 hex_reference_node(HexOrder order, int a) {
  if (a < 0 || a >= hex_node_count(order))
    throw std::out_of_range(fmt::format("hex_reference_node: local node {} out of range", a));
  return Vec3(kNodes[a][0], kNodes[a][1], kNodes[a][2]);
}

void hex_shape(HexOrder order, const Vec3& xi, std::span<double> N, std::span<double> dN) {
  const int nen = hex_node_count(order);
  for (int a = 0; a < nen; ++a) {
    double L[3], dL[3];
    for (int k = 0; k < 3; ++k) lagrange1d(order, kNodes[a][k], xi[k], L[k], dL[k]);
    N[a] = L[0] * L[1] * L[2];
    dN[3 * a + 0] = dL[0] * L[1] * L[2];
    dN[3 * a + 1] = L[0] * dL[1] * L[2];
    dN[3 * a + 2] = L[0] * L[1] * dL[2];
  }
}

HexFace hex_face(int face) {
  static constexpr HexFace faces[6] = {{2, -1}, {1, -1}, {0, -1}, {0, 1}, {1, 1}, {2, 1}};
  if (face < 0 || face > 5)
    throw std::out_of_range(fmt::format("hex_face: face {} not in 0..5", face));
  return faces[face];
}

std::vector<int> hex_face_nodes(HexOrder order, int face) {
  const HexFace f = hex_face(face);
  std::vector<int> nodes;
  for (int a = 0; a < hex_node_count(order); ++a)
    if (kNodes[a][f.axis] == f.side) nodes.push_back(a);
  return nodes;
}

namespace {
void gauss1d(int n, std::vector<double>& x, std::vector<double>& w) {
  switch (n) {
    case 1:
      x = {0.0};
      w = {2.0};
      return;
    case 2:
      x = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
      w = {1.0, 1.0};
      return;
    case 3:
      x = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
      w = {5.0 / 9, 8.0 / 9, 5.0 / 9};
      return;
    case 4: {
      const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(1.2));
      const double b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(1.2));
      const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
      x = {-b, -a, a, b};
      w = {wb, wa, wa, wb};
      return;
    }
    default:
      throw std::invalid_argument(
          fmt::format("Gauss rule with {} points per direction: only 1..4 are available", n));
  }
}
}  // namespace

QuadratureRule gauss_hex(std::array<int, 3> n) {
  std::vector<double> x[3], w[3];
  for (int k = 0; k < 3; ++k) gauss1d(n[k], x[k], w[k]);
  QuadratureRule q;
  for (std::size_t k = 0; k < x[2].size(); ++k)
    for (std::size_t j = 0; j < x[1].size(); ++j)
      for (std::size_t i = 0; i < x[0].size(); ++i) {
        q.points.emplace_back(x[0][i], x[1][j], x[2][k]);
        q.weights.push_back(w[0][i] * w[1][j] * w[2][k]);
      }
  return q;
}

QuadratureRule gauss_face(int face, int n) {
  const HexFace f = hex_face(face);
  std::vector<double> x, w;
  gauss1d(n, x, w);
  const int s = (f.axis + 1) % 3, t = (f.axis + 2) % 3;
  QuadratureRule q;
  for (std::size_t j = 0; j < x.size(); ++j)
    for (std::size_t i = 0; i < x.size(); ++i) {
      Vec3 p;
      p[f.axis] = f.side;
      p[s] = x[i];
      p[t] = x[j];
      q.points.push_back(p);
      q.weights.push_back(w[i] * w[j]);
    }
  return q;
}

std::array<int, 3> default_gauss(HexOrder order) {
  return order == HexOrder::q1 ? std::array<int, 3>{2, 2, 2} : std::array<int, 3>{3, 3, 3};
}

}  // namespace valsalva::structure
