// Sum-factorised explicit internal forces for Q2 hexahedra with a tensor Gauss rule (Orszag,
// J. Comput. Phys. 37:70, 1980; Kronbichler & Kormann, Comput. Fluids 63:135, 2012, for the
// finite-element form, including the vectorisation across elements used here).
//
// - Reference gradients dx/dxi at all Gauss points are three 1D sweeps per direction instead of a
//   27 x 27 product, and the force accumulation F_a = -sum_g Q_g(i,k) dN_a/dxi_k(g) is the
//   transposed sweep. The 1D Lagrange tables at the Gauss points are compile-time constants, so
//   the zeros and ones of the centre point cost nothing.
// - Elements are processed in packs of simd::kLanes (structure of arrays): every operation
//   acts on one pack register, which plain SSE2 provides.
// - Quasi-incompressible neo-Hookean, P = G J^-2/3 (F - I1/3 F^-T) + K ln J F^-T: with
//   g = dx/dxi and F = g Jinv (Jinv = dxi/dX), the quantity the sweep needs is
//     Q = w P Jinv^T = w G J^-2/3 g M + w (K ln J - G J^-2/3 I1/3) cof(g) / det g,
//   M = Jinv Jinv^T (symmetric, stored per point), I1 = (g M) : g, J = det g det Jinv; one log,
//   one exp and one division per point, no 3x3 products with Jinv. Other laws call
//   Material::pk1 lane by lane.
// Same arithmetic as SolidForces::forces_kernel up to round-off (tests/structure).
#include <algorithm>

#include "structure/simd_math.hpp"
#include "structure/solid_forces.hpp"

namespace valsalva::structure {

using simd::kLanes;
using simd::Vd;

namespace {

// 1D quadratic Lagrange basis on the nodes {-1, 0, 1} at the NQ Gauss points, as the
// five operations the sweeps need: values (interp), derivatives (deriv) and their transposes.
// Tables at the first point x0 = -xg; the last point mirrors it (B(x) = B(-x) reversed,
// D(x) = -D(-x) reversed), exactly in floating point.
template <int NQ>
constexpr double gauss_x = 0;
template <>
constexpr double gauss_x<3> = 0x1.8c97ef43f7248p-1;  // sqrt(0.6) as gauss1d computes it
template <>
constexpr double gauss_x<2> = 0x1.279a74590331dp-1;  // 1/sqrt(3) as gauss1d computes it

template <int NQ>
struct LineTables {
  static constexpr double xg = gauss_x<NQ>;
  static constexpr double x = -xg;
  static constexpr double b0 = 0.5 * x * (x - 1), b1 = 1 - x * x, b2 = 0.5 * x * (x + 1);
  static constexpr double d0 = x - 0.5, d1 = -2 * x, d2 = x + 0.5;
};

template <int NQ>
struct Line;

template <>
struct Line<3> : LineTables<3> {
  template <class T>
  static void interp(T u0, T u1, T u2, T* v, int s) {
    v[0] = b0 * u0 + b1 * u1 + b2 * u2;
    v[s] = u1;
    v[2 * s] = b2 * u0 + b1 * u1 + b0 * u2;
  }
  template <class T>
  static void deriv(T u0, T u1, T u2, T* v, int s) {
    v[0] = d0 * u0 + d1 * u1 + d2 * u2;
    v[s] = 0.5 * (u2 - u0);
    v[2 * s] = -d2 * u0 - d1 * u1 - d0 * u2;
  }
  template <class T>  // n_i = sum_p B[p][i] v_p
  static void interp_t(const T* v, int s, T& n0, T& n1, T& n2) {
    n0 = b0 * v[0] + b2 * v[2 * s];
    n1 = b1 * v[0] + v[s] + b1 * v[2 * s];
    n2 = b2 * v[0] + b0 * v[2 * s];
  }
  template <class T>
  static void deriv_t(const T* v, int s, T& n0, T& n1, T& n2) {
    n0 = d0 * v[0] - 0.5 * v[s] - d2 * v[2 * s];
    n1 = d1 * v[0] - d1 * v[2 * s];
    n2 = d2 * v[0] + 0.5 * v[s] - d0 * v[2 * s];
  }
};

template <>
struct Line<2> : LineTables<2> {
  template <class T>
  static void interp(T u0, T u1, T u2, T* v, int s) {
    v[0] = b0 * u0 + b1 * u1 + b2 * u2;
    v[s] = b2 * u0 + b1 * u1 + b0 * u2;
  }
  template <class T>
  static void deriv(T u0, T u1, T u2, T* v, int s) {
    v[0] = d0 * u0 + d1 * u1 + d2 * u2;
    v[s] = -d2 * u0 - d1 * u1 - d0 * u2;
  }
  template <class T>
  static void interp_t(const T* v, int s, T& n0, T& n1, T& n2) {
    n0 = b0 * v[0] + b2 * v[s];
    n1 = b1 * v[0] + b1 * v[s];
    n2 = b2 * v[0] + b0 * v[s];
  }
  template <class T>
  static void deriv_t(const T* v, int s, T& n0, T& n1, T& n2) {
    n0 = d0 * v[0] - d2 * v[s];
    n1 = d1 * v[0] - d1 * v[s];
    n2 = d2 * v[0] - d0 * v[s];
  }
};

// u[i + 3 j + 9 k] nodal values -> d/dxi, d/deta, d/dzeta at Gauss point p + NX (q + NY r).
template <int NX, int NY, int NZ>
inline void gradient(const Vd* u, Vd* gx, Vd* gy, Vd* gz) {
  using LX = Line<NX>;
  using LY = Line<NY>;
  using LZ = Line<NZ>;
  Vd A0[9][NX], A1[9][NX];  // [k j][p]: value and xi-derivative along xi lines
  for (int kj = 0; kj < 9; ++kj) {
    LX::interp(u[3 * kj], u[3 * kj + 1], u[3 * kj + 2], A0[kj], 1);
    LX::deriv(u[3 * kj], u[3 * kj + 1], u[3 * kj + 2], A1[kj], 1);
  }
  Vd T1[3][NY][NX], T2[3][NY][NX], T3[3][NY][NX];  // [k][q][p]
  for (int k = 0; k < 3; ++k)
    for (int p = 0; p < NX; ++p) {
      const int r0 = 3 * k;
      LY::interp(A1[r0][p], A1[r0 + 1][p], A1[r0 + 2][p], &T1[k][0][p], NX);
      LY::deriv(A0[r0][p], A0[r0 + 1][p], A0[r0 + 2][p], &T2[k][0][p], NX);
      LY::interp(A0[r0][p], A0[r0 + 1][p], A0[r0 + 2][p], &T3[k][0][p], NX);
    }
  constexpr int sz = NX * NY;
  for (int q = 0; q < NY; ++q)
    for (int p = 0; p < NX; ++p) {
      const int g = p + NX * q;
      LZ::interp(T1[0][q][p], T1[1][q][p], T1[2][q][p], gx + g, sz);
      LZ::interp(T2[0][q][p], T2[1][q][p], T2[2][q][p], gy + g, sz);
      LZ::deriv(T3[0][q][p], T3[1][q][p], T3[2][q][p], gz + g, sz);
    }
}

// Transpose of gradient(): fe[i + 3 j + 9 k] += sum_g (hx dN/dxi + hy dN/deta + hz dN/dzeta).
template <int NX, int NY, int NZ>
inline void gradient_transpose(const Vd* hx, const Vd* hy, const Vd* hz, Vd* fe) {
  using LX = Line<NX>;
  using LY = Line<NY>;
  using LZ = Line<NZ>;
  constexpr int sz = NX * NY;
  Vd T1[3][NY][NX], T2[3][NY][NX], T3[3][NY][NX];
  for (int q = 0; q < NY; ++q)
    for (int p = 0; p < NX; ++p) {
      const int g = p + NX * q;
      LZ::interp_t(hx + g, sz, T1[0][q][p], T1[1][q][p], T1[2][q][p]);
      LZ::interp_t(hy + g, sz, T2[0][q][p], T2[1][q][p], T2[2][q][p]);
      LZ::deriv_t(hz + g, sz, T3[0][q][p], T3[1][q][p], T3[2][q][p]);
    }
  Vd A0[9][NX], A1[9][NX];
  for (int k = 0; k < 3; ++k)
    for (int p = 0; p < NX; ++p) {
      const int r0 = 3 * k;
      LY::interp_t(&T1[k][0][p], NX, A1[r0][p], A1[r0 + 1][p], A1[r0 + 2][p]);
      Vd a0, a1, a2, b0, b1, b2;
      LY::deriv_t(&T2[k][0][p], NX, a0, a1, a2);
      LY::interp_t(&T3[k][0][p], NX, b0, b1, b2);
      A0[r0][p] = a0 + b0;
      A0[r0 + 1][p] = a1 + b1;
      A0[r0 + 2][p] = a2 + b2;
    }
  for (int kj = 0; kj < 9; ++kj) {
    Vd a0, a1, a2, b0, b1, b2;
    LX::deriv_t(A1[kj], 1, a0, a1, a2);
    LX::interp_t(A0[kj], 1, b0, b1, b2);
    fe[3 * kj] += a0 + b0;
    fe[3 * kj + 1] += a1 + b1;
    fe[3 * kj + 2] += a2 + b2;
  }
}

// Q = w P Jinv^T of the neo-Hookean law at one Gauss point of a pack (see the header comment),
// written over g; returns J. geo: M00 M01 M02 M11 M12 M22, det Jinv, w.
inline Vd neo_hookean_point(double G, double K, const Vd* geo, Vd* g[3][3]) {
  const Vd g00 = *g[0][0], g01 = *g[0][1], g02 = *g[0][2];
  const Vd g10 = *g[1][0], g11 = *g[1][1], g12 = *g[1][2];
  const Vd g20 = *g[2][0], g21 = *g[2][1], g22 = *g[2][2];
  const Vd m00 = geo[0], m01 = geo[1], m02 = geo[2], m11 = geo[3], m12 = geo[4], m22 = geo[5];
  Vd H[3][3];
  const Vd gr[3][3] = {{g00, g01, g02}, {g10, g11, g12}, {g20, g21, g22}};
  for (int c = 0; c < 3; ++c) {
    H[c][0] = gr[c][0] * m00 + gr[c][1] * m01 + gr[c][2] * m02;
    H[c][1] = gr[c][0] * m01 + gr[c][1] * m11 + gr[c][2] * m12;
    H[c][2] = gr[c][0] * m02 + gr[c][1] * m12 + gr[c][2] * m22;
  }
  Vd I1 = H[0][0] * g00 + H[0][1] * g01 + H[0][2] * g02;
  I1 += H[1][0] * g10 + H[1][1] * g11 + H[1][2] * g12;
  I1 += H[2][0] * g20 + H[2][1] * g21 + H[2][2] * g22;
  const Vd c[3][3] = {{g11 * g22 - g12 * g21, g12 * g20 - g10 * g22, g10 * g21 - g11 * g20},
                      {g02 * g21 - g01 * g22, g00 * g22 - g02 * g20, g01 * g20 - g00 * g21},
                      {g01 * g12 - g02 * g11, g02 * g10 - g00 * g12, g00 * g11 - g01 * g10}};
  const Vd detg = g00 * c[0][0] + g01 * c[0][1] + g02 * c[0][2];
  const Vd J = detg * geo[6];
  const Vd lnJ = simd::vlog(J);
  const Vd GJ = G * simd::vexp((-2.0 / 3.0) * lnJ);
  const Vd a = geo[7] * GJ;
  const Vd b = geo[7] * (K * lnJ - GJ * I1 * (1.0 / 3.0)) / detg;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) *g[i][k] = a * H[i][k] + b * c[i][k];
  return J;
}

}  // namespace

struct SolidForces::SumFact {
  int nbatch = 0;
  std::vector<int> node;  // [batch][lexicographic node i + 3 j + 9 k][lane] -> mesh node
  bool neo_hookean = false;
  double G = 0, K = 0;
  std::vector<Vd> geo;  // neo-Hookean: [batch][gauss point][8] (see neo_hookean_point)
};

void SolidForces::setup_sumfact(const QuadratureRule& q, std::array<int, 3> gauss) {
  if (mesh_.order != HexOrder::q2 || gauss[0] != 3 || gauss[1] != 3 ||
      (gauss[2] != 3 && gauss[2] != 2))
    return;
  // The compile-time tables assume exactly the points gauss1d returns.
  if (q.points[0][0] != -Line<3>::xg ||
      q.points[0][2] != -(gauss[2] == 3 ? Line<3>::xg : Line<2>::xg))
    return;
  auto s = std::make_shared<SumFact>();
  int perm[27];  // lexicographic node -> Gmsh local node
  for (int a = 0; a < 27; ++a) {
    const Vec3 r = hex_reference_node(HexOrder::q2, a);
    perm[int(r[0] + 1) + 3 * int(r[1] + 1) + 9 * int(r[2] + 1)] = a;
  }
  const int ne = mesh_.num_elements();
  s->nbatch = (ne + kLanes - 1) / kLanes;
  s->node.resize(static_cast<std::size_t>(s->nbatch) * 27 * kLanes);
  // A partial last pack repeats the last element; its forces are not scattered.
  auto elem = [&](int b, int l) { return std::min(b * kLanes + l, ne - 1); };
  for (int b = 0; b < s->nbatch; ++b)
    for (int a = 0; a < 27; ++a)
      for (int l = 0; l < kLanes; ++l)
        s->node[(static_cast<std::size_t>(b) * 27 + a) * kLanes + l] =
            mesh_.element_nodes(elem(b, l))[perm[a]];
  if (const auto gk =
          element_materials_.empty() ? material_.neo_hookean_parameters() : std::nullopt) {
    s->neo_hookean = true;
    s->G = (*gk)[0];
    s->K = (*gk)[1];
    s->geo.resize(static_cast<std::size_t>(s->nbatch) * ngp_ * 8);
    for (int b = 0; b < s->nbatch; ++b)
      for (int g = 0; g < ngp_; ++g)
        for (int l = 0; l < kLanes; ++l) {
          const std::size_t eg = static_cast<std::size_t>(elem(b, l)) * ngp_ + g;
          const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Ji(&jinv_[9 * eg]);
          const Mat3 M = Ji * Ji.transpose();
          const double v[8] = {M(0, 0), M(0, 1), M(0, 2),          M(1, 1),
                               M(1, 2), M(2, 2), Ji.determinant(), wdetj_[eg]};
          Vd* dst = &s->geo[(static_cast<std::size_t>(b) * ngp_ + g) * 8];
          for (int i = 0; i < 8; ++i) dst[i][l] = v[i];
        }
  }
  sumfact_ = std::move(s);
}

template <int NX, int NY, int NZ>
double SolidForces::sumfact_kernel(const double* x, double* f) const {
  constexpr int NG = NX * NY * NZ;
  const SumFact& S = *sumfact_;
  const int ne = mesh_.num_elements();
  Vd minJ = simd::splat(1e300);
  double min_det = 1e300;
  for (int b = 0; b < S.nbatch; ++b) {
    const int* node = &S.node[static_cast<std::size_t>(b) * 27 * kLanes];
    Vd u[3][27];
    for (int a = 0; a < 27; ++a)
      for (int l = 0; l < kLanes; ++l) {
        const double* xa = x + 3 * node[a * kLanes + l];
        u[0][a][l] = xa[0];
        u[1][a][l] = xa[1];
        u[2][a][l] = xa[2];
      }
    Vd G[3][3][NG];  // [component][reference direction][gauss point]; then Q = w P Jinv^T
    for (int c = 0; c < 3; ++c) gradient<NX, NY, NZ>(u[c], G[c][0], G[c][1], G[c][2]);
    if (S.neo_hookean) {
      const Vd* geo = &S.geo[static_cast<std::size_t>(b) * NG * 8];
      for (int g = 0; g < NG; ++g) {
        Vd* gp[3][3] = {{&G[0][0][g], &G[0][1][g], &G[0][2][g]},
                        {&G[1][0][g], &G[1][1][g], &G[1][2][g]},
                        {&G[2][0][g], &G[2][1][g], &G[2][2][g]}};
        minJ = simd::vmin(minJ, neo_hookean_point(S.G, S.K, geo + 8 * g, gp));
      }
    } else {
      for (int l = 0; l < kLanes; ++l) {
        const int e = std::min(b * kLanes + l, ne - 1);
        const double* ji = jinv_.data() + static_cast<std::size_t>(e) * NG * 9;
        const double* wd = wdetj_.data() + static_cast<std::size_t>(e) * NG;
        for (int g = 0; g < NG; ++g) {
          Mat3 dxdxi;
          for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) dxdxi(c, k) = G[c][k][g][l];
          const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Jinv(ji + 9 * g);
          const Mat3 F = dxdxi * Jinv;
          min_det = std::min(min_det, F.determinant());
          const Mat3 Q = wd[g] * material(e).pk1(F) * Jinv.transpose();
          for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) G[c][k][g][l] = Q(c, k);
        }
      }
    }
    Vd fe[3][27] = {};
    for (int c = 0; c < 3; ++c) gradient_transpose<NX, NY, NZ>(G[c][0], G[c][1], G[c][2], fe[c]);
    const int nl = std::min(kLanes, ne - b * kLanes);
    for (int a = 0; a < 27; ++a)
      for (int l = 0; l < nl; ++l) {
        double* fa = f + 3 * node[a * kLanes + l];
        fa[0] -= fe[0][a][l];
        fa[1] -= fe[1][a][l];
        fa[2] -= fe[2][a][l];
      }
  }
  for (int l = 0; l < kLanes; ++l) min_det = std::min(min_det, minJ[l]);
  return min_det;
}

template double SolidForces::sumfact_kernel<3, 3, 3>(const double*, double*) const;
template double SolidForces::sumfact_kernel<3, 3, 2>(const double*, double*) const;

}  // namespace valsalva::structure
