#include "structure/stress_recovery.hpp"

#include <Eigen/Eigenvalues>
#include <span>
#include <vector>

#include "structure/hex_element.hpp"

namespace valsalva::structure {

double von_mises(const Mat3& s) {
  const Mat3 dev = s - s.trace() / 3 * Mat3::Identity();
  return std::sqrt(1.5 * dev.squaredNorm());
}

NodalStress nodal_stress(const SolidForces& forces, const Eigen::Matrix3Xd& x) {
  const SolidMesh& m = forces.mesh();
  const int n = m.num_nodes(), nen = m.nodes_per_element();
  Eigen::Matrix<double, 6, Eigen::Dynamic> sig =
      Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n);
  Eigen::Matrix<double, 6, Eigen::Dynamic> strain = sig;
  Eigen::VectorXd count = Eigen::VectorXd::Zero(n);
  for (int e = 0; e < m.num_elements(); ++e)
    for (int a = 0; a < nen; ++a) {
      const Mat3 F = forces.deformation_gradient(x, e, hex_reference_node(m.order, a));
      const Mat3 s = forces.material(e).pk1(F) * F.transpose() / F.determinant();
      const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
      const int node = m.element_nodes(e)[a];
      sig.col(node) +=
          Eigen::Matrix<double, 6, 1>(s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2));
      strain.col(node) +=
          Eigen::Matrix<double, 6, 1>(E(0, 0), E(1, 1), E(2, 2), E(0, 1), E(1, 2), E(0, 2));
      count[node] += 1;
    }
  NodalStress out;
  out.von_mises.resize(n);
  out.principal_stress.resize(3, n);
  out.principal_strain.resize(3, n);
  auto unpack = [](const Eigen::Matrix<double, 6, 1>& v) {
    Mat3 t;
    t << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
    return t;
  };
  for (int i = 0; i < n; ++i) {
    if (count[i] > 0) {
      sig.col(i) /= count[i];
      strain.col(i) /= count[i];
    }
    const Mat3 s = unpack(sig.col(i)), E = unpack(strain.col(i));
    out.von_mises[i] = von_mises(s);
    out.principal_stress.col(i) =
        Eigen::SelfAdjointEigenSolver<Mat3>(s, Eigen::EigenvaluesOnly).eigenvalues().reverse();
    out.principal_strain.col(i) =
        Eigen::SelfAdjointEigenSolver<Mat3>(E, Eigen::EigenvaluesOnly).eigenvalues().reverse();
  }
  out.cauchy = std::move(sig);
  return out;
}

GaussPointStress gauss_point_stress(const SolidForces& forces, const Eigen::Matrix3Xd& x) {
  const SolidMesh& m = forces.mesh();
  const QuadratureRule rule = gauss_hex(default_gauss(m.order));
  const int nen = m.nodes_per_element(), ngp = rule.size();
  std::vector<double> N(static_cast<std::size_t>(ngp) * nen), dN(3 * N.size());
  for (int g = 0; g < ngp; ++g)
    hex_shape(m.order, rule.points[g], std::span(N).subspan(std::size_t(g) * nen, nen),
              std::span(dN).subspan(std::size_t(g) * 3 * nen, 3 * nen));
  GaussPointStress out;
  out.points_per_element = ngp;
  out.von_mises.resize(static_cast<long>(m.num_elements()) * ngp);
  out.position.resize(3, out.von_mises.size());
  for (int e = 0; e < m.num_elements(); ++e) {
    const int* en = m.element_nodes(e);
    for (int g = 0; g < ngp; ++g) {
      Mat3 dX = Mat3::Zero(), dx = Mat3::Zero();
      Vec3 at = Vec3::Zero();
      for (int a = 0; a < nen; ++a) {
        at += x.col(en[a]) * N[std::size_t(g) * nen + a];
        for (int k = 0; k < 3; ++k) {
          const double d = dN[std::size_t(g) * 3 * nen + 3 * a + k];
          dX.col(k) += m.X.col(en[a]) * d;
          dx.col(k) += x.col(en[a]) * d;
        }
      }
      const Mat3 F = dx * dX.inverse();
      const Mat3 s = forces.material(e).pk1(F) * F.transpose() / F.determinant();
      const long i = static_cast<long>(e) * ngp + g;
      out.von_mises[i] = von_mises(s);
      out.position.col(i) = at;
    }
  }
  return out;
}

}  // namespace valsalva::structure
