// Sum-factorised explicit internal forces for Q2 hexahedra with a tensor Gauss rule (Orszag,
// J. Comput. Phys. 37:70, 1980; Kronbichler & Kormann, Comput. Fluids 63:135, 2012, for the
// finite-element form). The reference gradients dx/dxi at all Gauss points are three 1D
// sweeps per direction instead of a 27 x 27 product: 648 instead of 2187 multiply-adds per
// component (3x3x3 rule), and the force accumulation F_a = -sum_g Q_g(i,k) dN_a/dxi_k(g) is the
// transposed sweep. Same arithmetic as SolidForces::forces_kernel up to round-off.
#include <cmath>

#include "structure/solid_forces.hpp"

namespace valsalva::structure {

struct SolidForces::SumFact {
  int perm[27];       // lexicographic node i + 3 j + 9 k -> Gmsh local node
  double B[3][3][3];  // [direction][gauss point][node]: 1D Lagrange value
  double D[3][3][3];  // derivative
};

void SolidForces::setup_sumfact(const QuadratureRule& q, std::array<int, 3> gauss) {
  if (mesh_.order != HexOrder::q2 || gauss[0] != 3 || gauss[1] != 3 ||
      (gauss[2] != 3 && gauss[2] != 2))
    return;
  auto s = std::make_shared<SumFact>();
  for (int a = 0; a < 27; ++a) {
    const Vec3 r = hex_reference_node(HexOrder::q2, a);
    s->perm[int(r[0] + 1) + 3 * int(r[1] + 1) + 9 * int(r[2] + 1)] = a;
  }
  const int stride[3] = {1, gauss[0], gauss[0] * gauss[1]};
  for (int d = 0; d < 3; ++d)
    for (int p = 0; p < gauss[d]; ++p) {
      const double x = q.points[p * stride[d]][d];
      const double L[3] = {0.5 * x * (x - 1), 1 - x * x, 0.5 * x * (x + 1)};
      const double dL[3] = {x - 0.5, -2 * x, x + 0.5};
      for (int i = 0; i < 3; ++i) {
        s->B[d][p][i] = L[i];
        s->D[d][p][i] = dL[i];
      }
    }
  sumfact_ = std::move(s);
}

namespace {

// u[k][j][i] nodal values -> derivatives along xi, eta, zeta at the Gauss points g[r][q][p].
template <int NX, int NY, int NZ, class SF>
inline void gradient(const SF& S, const double* u, double* gx, double* gy, double* gz) {
  double A0[9][NX], A1[9][NX];
  for (int kj = 0; kj < 9; ++kj)
    for (int p = 0; p < NX; ++p) {
      A0[kj][p] =
          S.B[0][p][0] * u[3 * kj] + S.B[0][p][1] * u[3 * kj + 1] + S.B[0][p][2] * u[3 * kj + 2];
      A1[kj][p] =
          S.D[0][p][0] * u[3 * kj] + S.D[0][p][1] * u[3 * kj + 1] + S.D[0][p][2] * u[3 * kj + 2];
    }
  double T1[3][NY][NX], T2[3][NY][NX], T3[3][NY][NX];
  for (int k = 0; k < 3; ++k)
    for (int q = 0; q < NY; ++q)
      for (int p = 0; p < NX; ++p) {
        const double* b = S.B[1][q];
        const double* d = S.D[1][q];
        T1[k][q][p] = b[0] * A1[3 * k][p] + b[1] * A1[3 * k + 1][p] + b[2] * A1[3 * k + 2][p];
        T2[k][q][p] = d[0] * A0[3 * k][p] + d[1] * A0[3 * k + 1][p] + d[2] * A0[3 * k + 2][p];
        T3[k][q][p] = b[0] * A0[3 * k][p] + b[1] * A0[3 * k + 1][p] + b[2] * A0[3 * k + 2][p];
      }
  for (int r = 0; r < NZ; ++r)
    for (int q = 0; q < NY; ++q)
      for (int p = 0; p < NX; ++p) {
        const double* b = S.B[2][r];
        const double* d = S.D[2][r];
        const int g = p + NX * (q + NY * r);
        gx[g] = b[0] * T1[0][q][p] + b[1] * T1[1][q][p] + b[2] * T1[2][q][p];
        gy[g] = b[0] * T2[0][q][p] + b[1] * T2[1][q][p] + b[2] * T2[2][q][p];
        gz[g] = d[0] * T3[0][q][p] + d[1] * T3[1][q][p] + d[2] * T3[2][q][p];
      }
}

// Transpose of gradient(): fe[k][j][i] += sum_g (hx dN/dxi + hy dN/deta + hz dN/dzeta).
template <int NX, int NY, int NZ, class SF>
inline void gradient_transpose(const SF& S, const double* hx, const double* hy, const double* hz,
                               double* fe) {
  double T1[3][NY][NX], T2[3][NY][NX], T3[3][NY][NX];
  for (int k = 0; k < 3; ++k)
    for (int q = 0; q < NY; ++q)
      for (int p = 0; p < NX; ++p) {
        double s1 = 0, s2 = 0, s3 = 0;
        for (int r = 0; r < NZ; ++r) {
          const int g = p + NX * (q + NY * r);
          s1 += S.B[2][r][k] * hx[g];
          s2 += S.B[2][r][k] * hy[g];
          s3 += S.D[2][r][k] * hz[g];
        }
        T1[k][q][p] = s1;
        T2[k][q][p] = s2;
        T3[k][q][p] = s3;
      }
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      double A0[NX], A1[NX];
      for (int p = 0; p < NX; ++p) {
        double s0 = 0, s1 = 0;
        for (int q = 0; q < NY; ++q) {
          s1 += S.B[1][q][j] * T1[k][q][p];
          s0 += S.D[1][q][j] * T2[k][q][p] + S.B[1][q][j] * T3[k][q][p];
        }
        A0[p] = s0;
        A1[p] = s1;
      }
      for (int i = 0; i < 3; ++i) {
        double s = 0;
        for (int p = 0; p < NX; ++p) s += S.D[0][p][i] * A1[p] + S.B[0][p][i] * A0[p];
        fe[i + 3 * j + 9 * k] += s;
      }
    }
}

}  // namespace

template <int NX, int NY, int NZ>
double SolidForces::sumfact_kernel(const double* x, double* f) const {
  constexpr int NG = NX * NY * NZ;
  const SumFact& S = *sumfact_;
  double min_det = 1e300;
  const int ne = mesh_.num_elements();
  for (int e = 0; e < ne; ++e) {
    const int* en = mesh_.element_nodes(e);
    int node[27];
    alignas(64) double u[3][27];
    for (int l = 0; l < 27; ++l) {
      node[l] = en[S.perm[l]];
      for (int c = 0; c < 3; ++c) u[c][l] = x[3 * node[l] + c];
    }
    alignas(64) double G[3][3][NG];  // [component][reference direction][gauss point]
    for (int c = 0; c < 3; ++c) gradient<NX, NY, NZ>(S, u[c], G[c][0], G[c][1], G[c][2]);
    const double* ji = jinv_.data() + static_cast<std::size_t>(e) * NG * 9;
    const double* wd = wdetj_.data() + static_cast<std::size_t>(e) * NG;
    for (int g = 0; g < NG; ++g) {
      Mat3 dxdxi;
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) dxdxi(c, k) = G[c][k][g];
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Jinv(ji + 9 * g);
      const Mat3 F = dxdxi * Jinv;
      min_det = std::min(min_det, F.determinant());
      const Mat3 Q = wd[g] * material_.pk1(F) * Jinv.transpose();
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) G[c][k][g] = Q(c, k);  // reuse G for the stress terms
    }
    alignas(64) double fe[3][27] = {};
    for (int c = 0; c < 3; ++c) gradient_transpose<NX, NY, NZ>(S, G[c][0], G[c][1], G[c][2], fe[c]);
    for (int l = 0; l < 27; ++l)
      for (int c = 0; c < 3; ++c) f[3 * node[l] + c] -= fe[c][l];
  }
  return min_det;
}

template double SolidForces::sumfact_kernel<3, 3, 3>(const double*, double*) const;
template double SolidForces::sumfact_kernel<3, 3, 2>(const double*, double*) const;

}  // namespace valsalva::structure
