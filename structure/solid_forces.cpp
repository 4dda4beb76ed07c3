#include "structure/solid_forces.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace valsalva::structure {

SolidForces::SolidForces(const SolidMesh& mesh, const Material& material, std::array<int, 3> gauss)
    : mesh_(mesh), material_(material), nen_(mesh.nodes_per_element()) {
  setup(gauss);
}

namespace {
const Material& first_material(const SolidMesh& mesh, const std::vector<const Material*>& m) {
  if (m.size() != static_cast<std::size_t>(mesh.num_elements()) || m.empty())
    throw std::invalid_argument(fmt::format("solid mesh {}: {} element materials for {} elements",
                                            mesh.source, m.size(), mesh.num_elements()));
  for (std::size_t e = 0; e < m.size(); ++e)
    if (!m[e])
      throw std::invalid_argument(
          fmt::format("solid mesh {}: element {} has no material", mesh.source, e));
  return *m.front();
}
}  // namespace

SolidForces::SolidForces(const SolidMesh& mesh, std::vector<const Material*> element_materials,
                         std::array<int, 3> gauss)
    : mesh_(mesh),
      material_(first_material(mesh, element_materials)),
      element_materials_(std::move(element_materials)),
      nen_(mesh.nodes_per_element()) {
  setup(gauss);
}

void SolidForces::setup(std::array<int, 3> gauss) {
  const SolidMesh& mesh = mesh_;
  const QuadratureRule q = gauss_hex(gauss);
  ngp_ = q.size();
  weights_ = q.weights;
  dNxi_.resize(ngp_ * 3 * nen_);
  std::vector<double> N(nen_), dN(3 * nen_);
  for (int g = 0; g < ngp_; ++g) {
    hex_shape(mesh.order, q.points[g], N, dN);
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < nen_; ++a) dNxi_[(g * 3 + k) * nen_ + a] = dN[3 * a + k];
  }
  const int ne = mesh.num_elements();
  jinv_.resize(static_cast<std::size_t>(ne) * ngp_ * 9);
  wdetj_.resize(static_cast<std::size_t>(ne) * ngp_);
  for (int e = 0; e < ne; ++e) {
    const int* en = mesh.element_nodes(e);
    for (int g = 0; g < ngp_; ++g) {
      Mat3 J = Mat3::Zero();  // dX/dxi
      for (int a = 0; a < nen_; ++a)
        for (int k = 0; k < 3; ++k) J.col(k) += mesh.X.col(en[a]) * dNxi_[(g * 3 + k) * nen_ + a];
      const double det = J.determinant();
      if (!(det > 0))
        throw std::runtime_error(
            fmt::format("solid mesh {}: element {} has reference Jacobian {:.3e} at "
                        "Gauss point {}",
                        mesh.source, e, det, g));
      const Mat3 Ji = J.inverse();
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          jinv_[(static_cast<std::size_t>(e) * ngp_ + g) * 9 + 3 * k + j] = Ji(k, j);
      wdetj_[static_cast<std::size_t>(e) * ngp_ + g] = q.weights[g] * det;
    }
  }
  gauss_ = gauss;
  setup_sumfact(q, gauss);
}

namespace {
void check_sizes(const SolidMesh& mesh, const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                 Eigen::Ref<Eigen::Matrix3Xd> f) {
  if (x.cols() != mesh.num_nodes() || f.cols() != mesh.num_nodes())
    throw std::invalid_argument(
        fmt::format("internal_forces: {} positions and {} force columns for a mesh of {} nodes",
                    x.cols(), f.cols(), mesh.num_nodes()));
  f.setZero();
}
}  // namespace

template <int NEN>
double SolidForces::forces_kernel(const double* x, double* f) const {
  double min_det = 1e300;
  const int ne = mesh_.num_elements();
  for (int e = 0; e < ne; ++e) {
    const int* en = mesh_.element_nodes(e);
    alignas(64) double xe[3][NEN];
    alignas(64) double fe[3][NEN] = {};
    for (int a = 0; a < NEN; ++a)
      for (int i = 0; i < 3; ++i) xe[i][a] = x[3 * en[a] + i];
    const double* ji = jinv_.data() + static_cast<std::size_t>(e) * ngp_ * 9;
    const double* wd = wdetj_.data() + static_cast<std::size_t>(e) * ngp_;
    for (int g = 0; g < ngp_; ++g) {
      const double* dN = dNxi_.data() + g * 3 * NEN;
      Mat3 dxdxi;  // dx/dxi
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
          double s = 0;
          for (int a = 0; a < NEN; ++a) s += xe[i][a] * dN[k * NEN + a];
          dxdxi(i, k) = s;
        }
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Jinv(ji + 9 * g);
      const Mat3 F = dxdxi * Jinv;
      min_det = std::min(min_det, F.determinant());
      const Mat3 Q = wd[g] * material(e).pk1(F) * Jinv.transpose();
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
          const double q = Q(i, k);
          for (int a = 0; a < NEN; ++a) fe[i][a] -= q * dN[k * NEN + a];
        }
    }
    for (int a = 0; a < NEN; ++a)
      for (int i = 0; i < 3; ++i) f[3 * en[a] + i] += fe[i][a];
  }
  return min_det;
}

double SolidForces::internal_forces(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                                    Eigen::Ref<Eigen::Matrix3Xd> f) const {
  check_sizes(mesh_, x, f);
  if (sumfact_) {
    if (gauss_[2] == 3) return sumfact_kernel<3, 3, 3>(x.data(), f.data());
    return sumfact_kernel<3, 3, 2>(x.data(), f.data());
  }
  return nen_ == 27 ? forces_kernel<27>(x.data(), f.data()) : forces_kernel<8>(x.data(), f.data());
}

double SolidForces::internal_forces_direct(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                                           Eigen::Ref<Eigen::Matrix3Xd> f) const {
  check_sizes(mesh_, x, f);
  return nen_ == 27 ? forces_kernel<27>(x.data(), f.data()) : forces_kernel<8>(x.data(), f.data());
}

Mat3 SolidForces::deformation_gradient(const Eigen::Matrix3Xd& x, int e, const Vec3& xi) const {
  std::vector<double> N(nen_), dN(3 * nen_);
  hex_shape(mesh_.order, xi, N, dN);
  Mat3 dX = Mat3::Zero(), dx = Mat3::Zero();
  const int* en = mesh_.element_nodes(e);
  for (int a = 0; a < nen_; ++a)
    for (int k = 0; k < 3; ++k) {
      dX.col(k) += mesh_.X.col(en[a]) * dN[3 * a + k];
      dx.col(k) += x.col(en[a]) * dN[3 * a + k];
    }
  return dx * dX.inverse();
}

std::pair<int, double> SolidForces::worst_element(const Eigen::Matrix3Xd& x) const {
  std::pair<int, double> worst{-1, 1e300};
  for (int e = 0; e < mesh_.num_elements(); ++e) {
    const int* en = mesh_.element_nodes(e);
    for (int g = 0; g < ngp_; ++g) {
      Mat3 dxdxi = Mat3::Zero();
      for (int a = 0; a < nen_; ++a)
        for (int k = 0; k < 3; ++k) dxdxi.col(k) += x.col(en[a]) * dNxi_[(g * 3 + k) * nen_ + a];
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Jinv(
          jinv_.data() + (static_cast<std::size_t>(e) * ngp_ + g) * 9);
      const double d = (dxdxi * Jinv).determinant();
      if (d < worst.second) worst = {e, d};
    }
  }
  return worst;
}

Eigen::SparseMatrix<double> SolidForces::stiffness_pattern() const {
  const int n = mesh_.num_nodes();
  std::vector<std::vector<int>> adj(n);
  for (int e = 0; e < mesh_.num_elements(); ++e) {
    const int* en = mesh_.element_nodes(e);
    for (int a = 0; a < nen_; ++a)
      for (int b = 0; b < nen_; ++b) adj[en[a]].push_back(en[b]);
  }
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    auto& v = adj[i];
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    for (int j : v)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) t.emplace_back(3 * j + r, 3 * i + c, 0.0);
  }
  Eigen::SparseMatrix<double> K(3 * n, 3 * n);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  return K;
}

double SolidForces::assemble(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& f,
                             Eigen::SparseMatrix<double>& K) const {
  const int n = mesh_.num_nodes();
  if (K.rows() != 3 * n || K.nonZeros() == 0) K = stiffness_pattern();
  std::fill(K.valuePtr(), K.valuePtr() + K.nonZeros(), 0.0);
  f.setZero(3, n);
  double min_det = 1e300;
  std::vector<double> gN(nen_ * 3);                            // grad_X N_a
  std::vector<double> T(static_cast<std::size_t>(nen_) * 27);  // T_a(i,k,L) = sum_J gN_aJ A_iJkL
  std::vector<double> Kloc(static_cast<std::size_t>(nen_) * nen_ * 9);
  Mat3 P;
  Mat9 A;
  for (int e = 0; e < mesh_.num_elements(); ++e) {
    const int* en = mesh_.element_nodes(e);
    std::fill(Kloc.begin(), Kloc.end(), 0.0);
    for (int g = 0; g < ngp_; ++g) {
      const double* dN = dNxi_.data() + g * 3 * nen_;
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Jinv(
          jinv_.data() + (static_cast<std::size_t>(e) * ngp_ + g) * 9);
      const double w = wdetj_[static_cast<std::size_t>(e) * ngp_ + g];
      Mat3 dxdxi = Mat3::Zero();
      for (int a = 0; a < nen_; ++a) {
        for (int J = 0; J < 3; ++J) {
          double s = 0;
          for (int k = 0; k < 3; ++k) s += Jinv(k, J) * dN[k * nen_ + a];
          gN[3 * a + J] = s;
        }
        for (int k = 0; k < 3; ++k) dxdxi.col(k) += x.col(en[a]) * dN[k * nen_ + a];
      }
      const Mat3 F = dxdxi * Jinv;
      min_det = std::min(min_det, F.determinant());
      material(e).pk1_tangent(F, P, A);
      for (int a = 0; a < nen_; ++a) {
        const Vec3 g3(gN[3 * a], gN[3 * a + 1], gN[3 * a + 2]);
        f.col(en[a]) -= w * (P * g3);
        for (int i = 0; i < 3; ++i)
          for (int kL = 0; kL < 9; ++kL) {
            double s = 0;
            for (int J = 0; J < 3; ++J) s += g3[J] * A(vidx(i, J), kL);
            T[a * 27 + i * 9 + kL] = w * s;
          }
      }
      for (int a = 0; a < nen_; ++a)
        for (int b = 0; b < nen_; ++b) {
          double* kb = &Kloc[(a * nen_ + b) * 9];
          const double* gb = &gN[3 * b];
          const double* ta = &T[a * 27];
          for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
              kb[3 * i + k] += ta[i * 9 + 3 * k] * gb[0] + ta[i * 9 + 3 * k + 1] * gb[1] +
                               ta[i * 9 + 3 * k + 2] * gb[2];
        }
    }
    // Scatter: in column 3*nb+k the rows 3*na .. 3*na+2 are consecutive in the CSC pattern.
    for (int b = 0; b < nen_; ++b)
      for (int k = 0; k < 3; ++k) {
        const int col = 3 * en[b] + k;
        const int* rb = K.innerIndexPtr() + K.outerIndexPtr()[col];
        const int* re = K.innerIndexPtr() + K.outerIndexPtr()[col + 1];
        for (int a = 0; a < nen_; ++a) {
          const int pos = static_cast<int>(std::lower_bound(rb, re, 3 * en[a]) - K.innerIndexPtr());
          for (int i = 0; i < 3; ++i) K.valuePtr()[pos + i] += Kloc[(a * nen_ + b) * 9 + 3 * i + k];
        }
      }
  }
  return min_det;
}

}  // namespace valsalva::structure
