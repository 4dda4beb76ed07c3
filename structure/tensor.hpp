// Small dense tensor helpers for finite-strain solid mechanics. Second-order tensors are Eigen
// 3x3 matrices; fourth-order tensors are 9x9 matrices with row 3*I+J and column 3*K+L, so that
// dA_IJ = T(3I+J, 3K+L) dB_KL (see Holzapfel, Nonlinear Solid Mechanics, Wiley 2000, ch. 1).
#pragma once

#include <Eigen/Dense>

namespace valsalva::structure {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat9 = Eigen::Matrix<double, 9, 9>;

inline int vidx(int i, int j) {
  return 3 * i + j;
}

// (A ⊗ B)_IJKL = A_IJ B_KL
inline Mat9 outer(const Mat3& A, const Mat3& B) {
  Mat9 T;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) T(vidx(i, j), vidx(k, l)) = A(i, j) * B(k, l);
  return T;
}

// (A ⊙ A)_IJKL = (A_IK A_JL + A_IL A_JK) / 2, the derivative -d(C^-1)/dC for A = C^-1.
inline Mat9 sym_product(const Mat3& A) {
  Mat9 T;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          T(vidx(i, j), vidx(k, l)) = 0.5 * (A(i, k) * A(j, l) + A(i, l) * A(j, k));
  return T;
}

// Inverse transpose of F through its cofactor matrix: F^-T = cof(F) / det F.
inline Mat3 cofactor(const Mat3& F) {
  Mat3 c;
  c(0, 0) = F(1, 1) * F(2, 2) - F(1, 2) * F(2, 1);
  c(0, 1) = F(1, 2) * F(2, 0) - F(1, 0) * F(2, 2);
  c(0, 2) = F(1, 0) * F(2, 1) - F(1, 1) * F(2, 0);
  c(1, 0) = F(0, 2) * F(2, 1) - F(0, 1) * F(2, 2);
  c(1, 1) = F(0, 0) * F(2, 2) - F(0, 2) * F(2, 0);
  c(1, 2) = F(0, 1) * F(2, 0) - F(0, 0) * F(2, 1);
  c(2, 0) = F(0, 1) * F(1, 2) - F(0, 2) * F(1, 1);
  c(2, 1) = F(0, 2) * F(1, 0) - F(0, 0) * F(1, 2);
  c(2, 2) = F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0);
  return c;
}

}  // namespace valsalva::structure
