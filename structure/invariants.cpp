#include "structure/invariants.hpp"

#include <cmath>

namespace valsalva::structure {

IsochoricInvariants isochoric_invariants(const Mat3& C, bool with_I2) {
  IsochoricInvariants r;
  const Mat3 I = Mat3::Identity();
  const double I3 = C.determinant();
  r.Cinv = C.inverse();
  const Mat9 CiCi = sym_product(r.Cinv);
  r.lnJ.value = 0.5 * std::log(I3);
  r.lnJ.d = 0.5 * r.Cinv;
  r.lnJ.dd = -0.5 * CiCi;
  const Mat9 gg = outer(r.lnJ.d, r.lnJ.d);

  // J^-2/3 = exp(-2/3 lnJ)
  r.Jm23 = std::exp(-2.0 / 3.0 * r.lnJ.value);
  r.dJm23 = -2.0 / 3.0 * r.Jm23 * r.lnJ.d;
  r.ddJm23 = r.Jm23 * (4.0 / 9.0 * gg - 2.0 / 3.0 * r.lnJ.dd);

  const double I1 = C.trace();
  r.I1bar.value = r.Jm23 * I1;
  r.I1bar.d = r.Jm23 * I + I1 * r.dJm23;
  r.I1bar.dd = outer(r.dJm23, I) + outer(I, r.dJm23) + I1 * r.ddJm23;

  if (with_I2) {
    // I2 = ((tr C)^2 - tr C^2)/2, dI2 = I1 I - C, d2I2 = I (x) I - sym identity.
    const double I2 = 0.5 * (I1 * I1 - (C * C).trace());
    const Mat3 dI2 = I1 * I - C;
    const Mat9 ddI2 = outer(I, I) - sym_product(I);
    const double Jm43 = r.Jm23 * r.Jm23;
    const Mat3 dJm43 = -4.0 / 3.0 * Jm43 * r.lnJ.d;
    const Mat9 ddJm43 = Jm43 * (16.0 / 9.0 * gg - 4.0 / 3.0 * r.lnJ.dd);
    r.I2bar.value = Jm43 * I2;
    r.I2bar.d = Jm43 * dI2 + I2 * dJm43;
    r.I2bar.dd = Jm43 * ddI2 + outer(dJm43, dI2) + outer(dI2, dJm43) + I2 * ddJm43;
  }
  return r;
}

Invariant fibre_invariant(const IsochoricInvariants& inv, const Mat3& C, const Vec3& a) {
  const double I4 = a.dot(C * a);
  const Mat3 aa = a * a.transpose();
  Invariant r;
  r.value = inv.Jm23 * I4;
  r.d = inv.Jm23 * aa + I4 * inv.dJm23;
  r.dd = outer(inv.dJm23, aa) + outer(aa, inv.dJm23) + I4 * inv.ddJm23;
  return r;
}

}  // namespace valsalva::structure
