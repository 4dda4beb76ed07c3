// St Venant–Kirchhoff (S = lambda tr(E) I + 2 mu E) and small-strain linear elasticity
// (Holzapfel 2000, sec. 6.5; the Turek–Hron CSM benchmarks use St Venant–Kirchhoff).
#include "structure/material.hpp"

namespace valsalva::structure {

namespace {

void lame(double E, double nu, double& lambda, double& mu) {
  lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  mu = E / (2 * (1 + nu));
}

// lambda I (x) I + 2 mu (sym identity)
Mat9 isotropic_tensor(double lambda, double mu) {
  const Mat3 I = Mat3::Identity();
  return lambda * outer(I, I) + 2 * mu * sym_product(I);
}

class StVenantKirchhoff final : public Hyperelastic {
 public:
  StVenantKirchhoff(double E, double nu) { lame(E, nu, lambda_, mu_); }
  std::string name() const override { return "st_venant_kirchhoff"; }
  double energy_C(const Mat3& C) const override {
    const Mat3 E = 0.5 * (C - Mat3::Identity());
    return 0.5 * lambda_ * E.trace() * E.trace() + mu_ * E.squaredNorm();
  }
  Mat3 pk2(const Mat3& C) const override {
    const Mat3 E = 0.5 * (C - Mat3::Identity());
    return lambda_ * E.trace() * Mat3::Identity() + 2 * mu_ * E;
  }
  void pk2_tangent(const Mat3& C, Mat3& S, Mat9& CC) const override {
    S = pk2(C);
    CC = isotropic_tensor(lambda_, mu_);
  }

 private:
  double lambda_ = 0, mu_ = 0;
};

class LinearElastic final : public Material {
 public:
  LinearElastic(double E, double nu) {
    lame(E, nu, lambda_, mu_);
    A_ = isotropic_tensor(lambda_, mu_);
  }
  std::string name() const override { return "linear_elastic"; }
  bool objective() const override { return false; }
  Mat3 pk1(const Mat3& F) const override {
    const Mat3 eps = 0.5 * (F + F.transpose()) - Mat3::Identity();
    return lambda_ * eps.trace() * Mat3::Identity() + 2 * mu_ * eps;
  }
  void pk1_tangent(const Mat3& F, Mat3& P, Mat9& A) const override {
    P = pk1(F);
    A = A_;
  }
  double energy(const Mat3& F) const override {
    const Mat3 eps = 0.5 * (F + F.transpose()) - Mat3::Identity();
    return 0.5 * lambda_ * eps.trace() * eps.trace() + mu_ * eps.squaredNorm();
  }

 private:
  double lambda_ = 0, mu_ = 0;
  Mat9 A_;
};

}  // namespace

std::unique_ptr<Material> make_st_venant_kirchhoff(double E, double nu) {
  return std::make_unique<StVenantKirchhoff>(E, nu);
}
std::unique_ptr<Material> make_linear_elastic(double E, double nu) {
  return std::make_unique<LinearElastic>(E, nu);
}

}  // namespace valsalva::structure
