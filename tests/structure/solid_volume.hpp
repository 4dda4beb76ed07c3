// Test helper: volume of a hexahedral solid mesh by Gauss quadrature of det(dX/dxi).
#pragma once

#include <vector>

#include "structure/solid_mesh.hpp"

namespace valsalva::structure::testing {

inline double solid_volume(const SolidMesh& m) {
  const auto q = gauss_hex(default_gauss(m.order));
  const int nen = m.nodes_per_element();
  std::vector<double> N(nen), dN(3 * nen);
  double V = 0;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int g = 0; g < q.size(); ++g) {
      hex_shape(m.order, q.points[g], N, dN);
      Mat3 J = Mat3::Zero();
      for (int n = 0; n < nen; ++n)
        for (int k = 0; k < 3; ++k) J.col(k) += m.X.col(m.element_nodes(e)[n]) * dN[3 * n + k];
      V += q.weights[g] * J.determinant();
    }
  return V;
}

}  // namespace valsalva::structure::testing
