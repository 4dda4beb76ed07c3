// Holzapfel–Gasser–Ogden law with fibre dispersion: Gasser, Ogden, Holzapfel, J. R. Soc.
// Interface 3:15-35 (2006), eq. 2.8 and 3.6, with the tension-only switch of Holzapfel, Gasser,
// Ogden, J. Elasticity 61:1-48 (2000): a fibre family contributes only when I4bar > 1.
#include <cmath>

#include "structure/invariants.hpp"
#include "structure/material.hpp"

namespace valsalva::structure {

namespace {

class Hgo final : public Hyperelastic {
 public:
  explicit Hgo(const HgoParameters& p) : p_(p) {
    const Vec3 e1 = p.e1.normalized(), e2 = p.e2.normalized();
    a_[0] = std::cos(p.gamma) * e1 + std::sin(p.gamma) * e2;
    a_[1] = std::cos(p.gamma) * e1 - std::sin(p.gamma) * e2;
  }
  std::string name() const override { return "hgo"; }

  double energy_C(const Mat3& C) const override {
    const IsochoricInvariants inv = isochoric_invariants(C, false);
    double W = 0.5 * p_.mu * (inv.I1bar.value - 3) + 0.5 * p_.K * inv.lnJ.value * inv.lnJ.value;
    for (const Vec3& a : a_) {
      const Invariant I4 = fibre_invariant(inv, C, a);
      if (I4.value <= 1) continue;
      const double E = p_.kappa * inv.I1bar.value + (1 - 3 * p_.kappa) * I4.value - 1;
      W += p_.k1 / (2 * p_.k2) * (std::exp(p_.k2 * E * E) - 1);
    }
    return W;
  }
  Mat3 pk2(const Mat3& C) const override {
    Mat3 S;
    Mat9 CC;
    pk2_tangent(C, S, CC);
    return S;
  }
  void pk2_tangent(const Mat3& C, Mat3& S, Mat9& CC) const override {
    const IsochoricInvariants inv = isochoric_invariants(C, false);
    S.setZero();
    CC.setZero();
    add_first(S, CC, 0.5 * p_.mu, inv.I1bar);
    add_first(S, CC, p_.K * inv.lnJ.value, inv.lnJ);
    add_second(CC, p_.K, inv.lnJ, inv.lnJ);
    for (const Vec3& a : a_) {
      const Invariant I4 = fibre_invariant(inv, C, a);
      if (I4.value <= 1) continue;
      // E = kappa I1bar + (1-3 kappa) I4bar - 1 as an "invariant" with its own derivatives.
      Invariant E;
      E.value = p_.kappa * inv.I1bar.value + (1 - 3 * p_.kappa) * I4.value - 1;
      E.d = p_.kappa * inv.I1bar.d + (1 - 3 * p_.kappa) * I4.d;
      E.dd = p_.kappa * inv.I1bar.dd + (1 - 3 * p_.kappa) * I4.dd;
      const double ex = std::exp(p_.k2 * E.value * E.value);
      add_first(S, CC, p_.k1 * E.value * ex, E);
      add_second(CC, p_.k1 * ex * (1 + 2 * p_.k2 * E.value * E.value), E, E);
    }
  }

 private:
  HgoParameters p_;
  Vec3 a_[2];
};

}  // namespace

std::unique_ptr<Material> make_hgo(const HgoParameters& p) {
  return std::make_unique<Hgo>(p);
}

}  // namespace valsalva::structure
