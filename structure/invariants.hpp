// Invariants of the right Cauchy–Green tensor C with their first and second derivatives with
// respect to C (symmetric forms, 9x9 layout of tensor.hpp), for invariant-based hyperelastic
// laws: S = 2 sum_i W_i dI_i/dC, CC = 4 sum_ij W_ij dI_i/dC (x) dI_j/dC + 4 sum_i W_i d2I_i/dC2.
// Isochoric invariants I1bar = J^-2/3 I1, I2bar = J^-4/3 I2, I4bar = J^-2/3 a.Ca (Holzapfel 2000,
// sec. 6.4); derivatives built from d(ln J)/dC = C^-1/2 and d2(ln J)/dC2 = -(C^-1 (.) C^-1)/2.
#pragma once

#include "structure/tensor.hpp"

namespace valsalva::structure {

struct Invariant {
  double value = 0;
  Mat3 d = Mat3::Zero();   // dI/dC
  Mat9 dd = Mat9::Zero();  // d2I/dC2
};

struct IsochoricInvariants {
  Invariant lnJ, I1bar, I2bar;
  Mat3 Cinv;
  double Jm23 = 1;  // J^-2/3
  Mat3 dJm23;       // d(J^-2/3)/dC
  Mat9 ddJm23;      // d2(J^-2/3)/dC2
};

IsochoricInvariants isochoric_invariants(const Mat3& C, bool with_I2);
// I4bar = J^-2/3 a.C a for a unit reference direction a.
Invariant fibre_invariant(const IsochoricInvariants& inv, const Mat3& C, const Vec3& a);

// Adds the contributions of W_i and W_ij to S and CC (see above).
inline void add_first(Mat3& S, Mat9& CC, double Wi, const Invariant& I) {
  S += 2 * Wi * I.d;
  CC += 4 * Wi * I.dd;
}
inline void add_second(Mat9& CC, double Wij, const Invariant& Ii, const Invariant& Ij) {
  CC += 4 * Wij * outer(Ii.d, Ij.d);
}

}  // namespace valsalva::structure
