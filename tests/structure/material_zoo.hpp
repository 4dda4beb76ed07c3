// The five constitutive laws with the parameters used by the structure tests, and closed-form
// energies W(lambda1, lambda2, lambda3) of diagonal F and W(gamma) of simple shear, written out
// by hand (independent of the tensor code) so that P_ii = dW/dlambda_i and P_12 = dW/dgamma.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "structure/material.hpp"

namespace valsalva::structure::testing {

struct ZooEntry {
  std::string name;
  std::unique_ptr<Material> material;
  double scale;  // a stress scale for relative tolerances
  // dW/dlambda_i for F = diag(l)
  std::function<Vec3(const Vec3& l)> dW_dlambda;
  // dW/dgamma for F = I + gamma e1 (x) e2
  std::function<double(double g)> dW_dgamma;
};

inline std::vector<ZooEntry> material_zoo() {
  std::vector<ZooEntry> zoo;
  {  // neo-Hookean, leaflet values
    const double G = 2.4e6, K = 1.6e6;
    zoo.push_back({"neo_hookean", make_neo_hookean(G, K), G,
                   [=](const Vec3& l) {
                     const double J = l.prod(), I1 = l.squaredNorm(), f = std::pow(J, -2.0 / 3);
                     Vec3 r;
                     for (int i = 0; i < 3; ++i)
                       r[i] = 0.5 * G * (2 * f * l[i] - 2.0 / 3 * f * I1 / l[i]) +
                              K * std::log(J) / l[i];
                     return r;
                   },
                   [=](double g) { return G * g; }});
  }
  {  // Mooney–Rivlin
    const double c10 = 0.3e6, c01 = 0.1e6, c11 = 0.05e6, K = 5e6;
    zoo.push_back({"mooney_rivlin", make_mooney_rivlin(c10, c01, c11, K), c10,
                   [=](const Vec3& l) {
                     const double J = l.prod(), f = std::pow(J, -2.0 / 3), f2 = f * f;
                     const Vec3 s = l.cwiseAbs2();
                     const double I1b = f * s.sum(),
                                  I2b = f2 * (s[0] * s[1] + s[1] * s[2] + s[0] * s[2]);
                     Vec3 r;
                     for (int i = 0; i < 3; ++i) {
                       const double dI1 = 2 * f * l[i] - 2.0 / 3 * I1b / l[i];
                       const double dI2 = 2 * f2 * l[i] * (s.sum() - s[i]) - 4.0 / 3 * I2b / l[i];
                       r[i] = (c10 + c11 * (I2b - 3)) * dI1 + (c01 + c11 * (I1b - 3)) * dI2 +
                              K * std::log(J) / l[i];
                     }
                     return r;
                   },
                   [=](double g) { return 2 * (c10 + c01) * g + 4 * c11 * g * g * g; }});
  }
  {  // HGO, aortic media values of Gasser et al. 2006 (k2 dimensionless)
    HgoParameters p;
    p.mu = 7.64e3 * 2;
    p.K = 1e6;
    p.k1 = 996.6e3;
    p.k2 = 524.6e-3;
    p.kappa = 0.226;
    p.gamma = 49.98 * M_PI / 180;
    zoo.push_back({"hgo", make_hgo(p), p.mu,
                   [=](const Vec3& l) {
                     const double J = l.prod(), f = std::pow(J, -2.0 / 3);
                     const double c = std::cos(p.gamma), s = std::sin(p.gamma);
                     const double I1b = f * l.squaredNorm(),
                                  I4b = f * (c * c * l[0] * l[0] + s * s * l[1] * l[1]);
                     const double E = p.kappa * I1b + (1 - 3 * p.kappa) * I4b - 1;
                     Vec3 r;
                     for (int i = 0; i < 3; ++i) {
                       const double dI1 = 2 * f * l[i] - 2.0 / 3 * I1b / l[i];
                       const double w4 = i == 0 ? c * c : (i == 1 ? s * s : 0.0);
                       const double dI4 = 2 * f * w4 * l[i] - 2.0 / 3 * I4b / l[i];
                       r[i] = 0.5 * p.mu * dI1 + p.K * std::log(J) / l[i];
                       if (I4b > 1)  // both families have the same I4 under diagonal F
                         r[i] += 2 * p.k1 * E * std::exp(p.k2 * E * E) *
                                 (p.kappa * dI1 + (1 - 3 * p.kappa) * dI4);
                     }
                     return r;
                   },
                   [=](double g) {
                     const double s = std::sin(p.gamma);
                     double r = p.mu * g;
                     for (double sf : {1.0, -1.0}) {
                       const double I4 = 1 + sf * g * std::sin(2 * p.gamma) + g * g * s * s;
                       if (I4 <= 1) continue;
                       const double E = p.kappa * g * g + (1 - 3 * p.kappa) * (I4 - 1);
                       const double dE =
                           2 * p.kappa * g +
                           (1 - 3 * p.kappa) * (sf * std::sin(2 * p.gamma) + 2 * g * s * s);
                       r += p.k1 * E * std::exp(p.k2 * E * E) * dE;
                     }
                     return r;
                   }});
  }
  {  // St Venant–Kirchhoff, Turek–Hron CSM2
    const double E = 5.6e6, nu = 0.4, lam = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu = E / (2 * (1 + nu));
    zoo.push_back({"st_venant_kirchhoff", make_st_venant_kirchhoff(E, nu), mu,
                   [=](const Vec3& l) {
                     const Vec3 Ed = 0.5 * (l.cwiseAbs2() - Vec3::Ones());
                     Vec3 r;
                     for (int i = 0; i < 3; ++i) r[i] = l[i] * (lam * Ed.sum() + 2 * mu * Ed[i]);
                     return r;
                   },
                   [=](double g) { return lam * g * g * g / 2 + mu * (g + g * g * g); }});
  }
  {  // linear elastic
    const double E = 1e6, nu = 0.3, lam = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu = E / (2 * (1 + nu));
    zoo.push_back({"linear_elastic", make_linear_elastic(E, nu), mu,
                   [=](const Vec3& l) {
                     const Vec3 e = l - Vec3::Ones();
                     return Vec3((lam * e.sum() * Vec3::Ones() + 2 * mu * e));
                   },
                   [=](double g) { return mu * g; }});
  }
  return zoo;
}

}  // namespace valsalva::structure::testing
