#include "structure/material.hpp"

namespace valsalva::structure {

// A_iJkL = delta_ik S_LJ + sum_IN F_iI CC_IJLN F_kN (push of dS/dE through F, Holzapfel 2000
// eq. 6.166 in index form).
void Hyperelastic::pk1_tangent(const Mat3& F, Mat3& P, Mat9& A) const {
  Mat3 S;
  Mat9 CC;
  pk2_tangent(F.transpose() * F, S, CC);
  P = F * S;
  // G(3I+J, 3k+L) = sum_N CC_IJLN F_kN
  Mat9 G;
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          double s = 0;
          for (int N = 0; N < 3; ++N) s += CC(vidx(I, J), vidx(L, N)) * F(k, N);
          G(vidx(I, J), vidx(k, L)) = s;
        }
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          double s = (i == k) ? S(L, J) : 0.0;
          for (int I = 0; I < 3; ++I) s += F(i, I) * G(vidx(I, J), vidx(k, L));
          A(vidx(i, J), vidx(k, L)) = s;
        }
}

}  // namespace valsalva::structure
