// Quasi-incompressible neo-Hookean and Mooney–Rivlin laws with the volumetric energy
// K/2 (ln J)^2 (Holzapfel 2000, sec. 6.5; the neo-Hookean form is the leaflet law of the
// reference study).
#include <cmath>

#include "structure/invariants.hpp"
#include "structure/material.hpp"

namespace valsalva::structure {

namespace {

class NeoHookean final : public Hyperelastic {
 public:
  NeoHookean(double G, double K) : G_(G), K_(K) {}
  std::string name() const override { return "neo_hookean"; }
  std::optional<std::array<double, 2>> neo_hookean_parameters() const override {
    return std::array<double, 2>{G_, K_};
  }

  double energy_C(const Mat3& C) const override {
    const double lnJ = 0.5 * std::log(C.determinant());
    return 0.5 * G_ * (std::exp(-2.0 / 3.0 * lnJ) * C.trace() - 3) + 0.5 * K_ * lnJ * lnJ;
  }
  Mat3 pk2(const Mat3& C) const override {
    const Mat3 Ci = C.inverse();
    const double lnJ = 0.5 * std::log(C.determinant());
    return G_ * std::exp(-2.0 / 3.0 * lnJ) * (Mat3::Identity() - C.trace() / 3 * Ci) +
           K_ * lnJ * Ci;
  }
  // Fast path for the explicit force loop: P = G J^-2/3 (F - I1/3 F^-T) + K ln J F^-T.
  Mat3 pk1(const Mat3& F) const override {
    const Mat3 cof = cofactor(F);
    const double J = F.row(0).dot(cof.row(0));
    const double lnJ = std::log(J);
    const Mat3 FinvT = cof / J;
    const double I1 = F.squaredNorm();
    return G_ * std::exp(-2.0 / 3.0 * lnJ) * (F - I1 / 3 * FinvT) + K_ * lnJ * FinvT;
  }
  void pk2_tangent(const Mat3& C, Mat3& S, Mat9& CC) const override {
    const IsochoricInvariants inv = isochoric_invariants(C, false);
    S.setZero();
    CC.setZero();
    add_first(S, CC, 0.5 * G_, inv.I1bar);
    add_first(S, CC, K_ * inv.lnJ.value, inv.lnJ);
    add_second(CC, K_, inv.lnJ, inv.lnJ);
  }

 private:
  double G_, K_;
};

class MooneyRivlin final : public Hyperelastic {
 public:
  MooneyRivlin(double C10, double C01, double C11, double K)
      : c10_(C10), c01_(C01), c11_(C11), K_(K) {}
  std::string name() const override { return "mooney_rivlin"; }

  double energy_C(const Mat3& C) const override {
    const IsochoricInvariants inv = isochoric_invariants(C, true);
    const double a = inv.I1bar.value - 3, b = inv.I2bar.value - 3, l = inv.lnJ.value;
    return c10_ * a + c01_ * b + c11_ * a * b + 0.5 * K_ * l * l;
  }
  Mat3 pk2(const Mat3& C) const override {
    Mat3 S;
    Mat9 CC;
    pk2_tangent(C, S, CC);
    return S;
  }
  void pk2_tangent(const Mat3& C, Mat3& S, Mat9& CC) const override {
    const IsochoricInvariants inv = isochoric_invariants(C, true);
    const double a = inv.I1bar.value - 3, b = inv.I2bar.value - 3;
    S.setZero();
    CC.setZero();
    add_first(S, CC, c10_ + c11_ * b, inv.I1bar);
    add_first(S, CC, c01_ + c11_ * a, inv.I2bar);
    add_first(S, CC, K_ * inv.lnJ.value, inv.lnJ);
    add_second(CC, c11_, inv.I1bar, inv.I2bar);
    add_second(CC, c11_, inv.I2bar, inv.I1bar);
    add_second(CC, K_, inv.lnJ, inv.lnJ);
  }

 private:
  double c10_, c01_, c11_, K_;
};

}  // namespace

std::unique_ptr<Material> make_neo_hookean(double G, double K) {
  return std::make_unique<NeoHookean>(G, K);
}
std::unique_ptr<Material> make_mooney_rivlin(double C10, double C01, double C11, double K) {
  return std::make_unique<MooneyRivlin>(C10, C01, C11, K);
}

}  // namespace valsalva::structure
