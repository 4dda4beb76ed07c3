#include "structure/loads.hpp"

#include <algorithm>

namespace valsalva::structure {

namespace {

// Calls fn(node_ids, N, dN, weight) at every Gauss point of a face, with the rule exact for the
// face's polynomial degree in each direction.
template <class Fn>
void for_face_points(const SolidMesh& mesh, const FaceRef& fr, Fn&& fn) {
  const int nen = mesh.nodes_per_element();
  const QuadratureRule q = gauss_face(fr.face, static_cast<int>(mesh.order) + 2);
  std::vector<double> N(nen), dN(3 * nen);
  for (int g = 0; g < q.size(); ++g) {
    hex_shape(mesh.order, q.points[g], N, dN);
    fn(mesh.element_nodes(fr.element), N, dN, q.weights[g]);
  }
}

// x_s x x_t with the orientation of the outward normal.
Vec3 area_vector(const SolidMesh& mesh, const FaceRef& fr, const Eigen::Matrix3Xd& x, const int* en,
                 const std::vector<double>& dN, Vec3& xs, Vec3& xt) {
  const HexFace f = hex_face(fr.face);
  const int s = (f.axis + 1) % 3, t = (f.axis + 2) % 3;
  xs.setZero();
  xt.setZero();
  for (int a = 0; a < mesh.nodes_per_element(); ++a) {
    xs += x.col(en[a]) * dN[3 * a + s];
    xt += x.col(en[a]) * dN[3 * a + t];
  }
  return f.side * xs.cross(xt);
}

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return m;
}

}  // namespace

void add_body_force(const SolidMesh& mesh, const Vec3& b0, Eigen::Matrix3Xd& f) {
  const int nen = mesh.nodes_per_element();
  const QuadratureRule q = gauss_hex(default_gauss(mesh.order));
  std::vector<double> N(nen), dN(3 * nen);
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* en = mesh.element_nodes(e);
    for (int g = 0; g < q.size(); ++g) {
      hex_shape(mesh.order, q.points[g], N, dN);
      Mat3 J = Mat3::Zero();
      for (int a = 0; a < nen; ++a)
        for (int k = 0; k < 3; ++k) J.col(k) += mesh.X.col(en[a]) * dN[3 * a + k];
      const double w = q.weights[g] * J.determinant();
      for (int a = 0; a < nen; ++a) f.col(en[a]) += w * N[a] * b0;
    }
  }
}

void add_dead_traction(const SolidMesh& mesh, const std::vector<FaceRef>& faces, const Vec3& t0,
                       Eigen::Matrix3Xd& f) {
  for (const FaceRef& fr : faces)
    for_face_points(
        mesh, fr,
        [&](const int* en, const std::vector<double>& N, const std::vector<double>& dN, double w) {
          Vec3 xs, xt;
          const double dA = area_vector(mesh, fr, mesh.X, en, dN, xs, xt).norm() * w;
          for (int a = 0; a < mesh.nodes_per_element(); ++a) f.col(en[a]) += N[a] * dA * t0;
        });
}

void add_follower_pressure(const SolidMesh& mesh, const std::vector<FaceRef>& faces, double p,
                           const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& f,
                           Eigen::SparseMatrix<double>* K) {
  const int nen = mesh.nodes_per_element();
  for (const FaceRef& fr : faces) {
    const HexFace hf = hex_face(fr.face);
    const int s = (hf.axis + 1) % 3, t = (hf.axis + 2) % 3;
    for_face_points(
        mesh, fr,
        [&](const int* en, const std::vector<double>& N, const std::vector<double>& dN, double w) {
          Vec3 xs, xt;
          const Vec3 n = area_vector(mesh, fr, x, en, dN, xs, xt);
          for (int a = 0; a < nen; ++a) f.col(en[a]) -= p * w * N[a] * n;
          if (!K) return;
          // d(n)/dx_b = side (-dN_b/ds [x_t]x + dN_b/dt [x_s]x); K_ab = -df_a/dx_b = p w N_a
          // dn/dx_b.
          const Mat3 St = skew(xt), Ss = skew(xs);
          for (int b = 0; b < nen; ++b) {
            if (dN[3 * b + s] == 0 && dN[3 * b + t] == 0) continue;
            const Mat3 dn = hf.side * (-dN[3 * b + s] * St + dN[3 * b + t] * Ss);
            for (int a = 0; a < nen; ++a) {
              if (N[a] == 0) continue;
              const Mat3 blk = p * w * N[a] * dn;
              for (int k = 0; k < 3; ++k) {
                const int col = 3 * en[b] + k;
                const int* rb = K->innerIndexPtr() + K->outerIndexPtr()[col];
                const int* re = K->innerIndexPtr() + K->outerIndexPtr()[col + 1];
                const int pos =
                    static_cast<int>(std::lower_bound(rb, re, 3 * en[a]) - K->innerIndexPtr());
                for (int i = 0; i < 3; ++i) K->valuePtr()[pos + i] += blk(i, k);
              }
            }
          }
        });
  }
}

double surface_area(const SolidMesh& mesh, const std::vector<FaceRef>& faces,
                    const Eigen::Matrix3Xd& x) {
  double A = 0;
  for (const FaceRef& fr : faces)
    for_face_points(
        mesh, fr,
        [&](const int* en, const std::vector<double>&, const std::vector<double>& dN, double w) {
          Vec3 xs, xt;
          A += area_vector(mesh, fr, x, en, dN, xs, xt).norm() * w;
        });
  return A;
}

}  // namespace valsalva::structure
