// Constitutive laws. Every material gives the first Piola–Kirchhoff stress P(F) and its
// derivative A = dP/dF (the tangent used by the Newton solver); hyperelastic laws are defined by
// a strain energy W(C) and also give S(C) = 2 dW/dC and the material tangent CC = 4 d2W/dC2.
// Parameters are SI (Pa). Formulas: Holzapfel, Nonlinear Solid Mechanics (Wiley 2000), ch. 6.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "structure/tensor.hpp"

namespace valsalva::structure {

class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  // First Piola–Kirchhoff stress. Called once per Gauss point by the explicit force loop, so it
  // must not allocate.
  virtual Mat3 pk1(const Mat3& F) const = 0;
  // P and A_{iJkL} = dP_iJ / dF_kL (row 3i+J, column 3k+L).
  virtual void pk1_tangent(const Mat3& F, Mat3& P, Mat9& A) const = 0;
  // Strain energy per reference volume (NaN for a law without one).
  virtual double energy(const Mat3& F) const = 0;
  // Whether P(QF) = Q P(F) for rotations Q (false only for the small-strain law).
  virtual bool objective() const { return true; }
  // {G, K} when this is the quasi-incompressible neo-Hookean law below: the explicit force
  // kernel then evaluates P inline on packs of elements instead of calling pk1 per point.
  virtual std::optional<std::array<double, 2>> neo_hookean_parameters() const {
    return std::nullopt;
  }
};

// Laws written in terms of C = F^T F: P = F S, A_iJkL = delta_ik S_LJ + F_iI CC_IJLN F_kN.
class Hyperelastic : public Material {
 public:
  virtual double energy_C(const Mat3& C) const = 0;
  virtual Mat3 pk2(const Mat3& C) const = 0;
  virtual void pk2_tangent(const Mat3& C, Mat3& S, Mat9& CC) const = 0;

  Mat3 pk1(const Mat3& F) const override { return F * pk2(F.transpose() * F); }
  void pk1_tangent(const Mat3& F, Mat3& P, Mat9& A) const override;
  double energy(const Mat3& F) const override { return energy_C(F.transpose() * F); }
};

// W = G/2 (I1bar - 3) + K/2 (ln J)^2 (the leaflet law of the reference study).
std::unique_ptr<Material> make_neo_hookean(double G, double K);
// W = C10 (I1bar-3) + C01 (I2bar-3) + C11 (I1bar-3)(I2bar-3) + K/2 (ln J)^2.
std::unique_ptr<Material> make_mooney_rivlin(double C10, double C01, double C11, double K);
// Holzapfel, Gasser, Ogden, J. R. Soc. Interface 3:15-35 (2006), with the volumetric term above:
// W = mu/2 (I1bar-3) + K/2 (ln J)^2 + sum_{f=1,2} k1/(2 k2) [exp(k2 E_f^2) - 1],
// E_f = kappa I1bar + (1 - 3 kappa) I4bar_f - 1, fibres a_f = cos(gamma) e1 +- sin(gamma) e2;
// a family contributes only when stretched (I4bar_f > 1), as in Holzapfel et al. 2000.
struct HgoParameters {
  double mu = 0, K = 0, k1 = 0, k2 = 0, kappa = 0, gamma = 0;
  Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY();
};
std::unique_ptr<Material> make_hgo(const HgoParameters& p);
// S = lambda tr(E) I + 2 mu E, E = (C - I)/2.
std::unique_ptr<Material> make_st_venant_kirchhoff(double E, double nu);
// Small strain: P = sigma = lambda tr(eps) I + 2 mu eps, eps = sym(F) - I (not objective).
std::unique_ptr<Material> make_linear_elastic(double E, double nu);

// The constitutive laws of make_material (the scene key <structure>.material).
enum class MaterialLaw { neo_hookean, mooney_rivlin, hgo, st_venant_kirchhoff, linear_elastic };

// The scene names, in the order of the enum: "neo_hookean", "mooney_rivlin", "hgo",
// "st_venant_kirchhoff", "linear_elastic".
const std::vector<std::string>& material_law_names();
std::string to_string(MaterialLaw law);
// std::invalid_argument naming the value and the accepted names for an unknown name.
MaterialLaw parse_material_law(std::string_view name);

// Builds a material from its law and named parameters (SI), as read from a scene:
//   neo_hookean {G, K}, mooney_rivlin {C10, C01, C11, K}, hgo {mu, K, k1, k2, kappa, gamma},
//   st_venant_kirchhoff {E, nu}, linear_elastic {E, nu}.
// An unknown or missing parameter, or a non-physical value throws a message naming `where`
// (e.g. "scene.toml:12 [solid.material]") and the offending key and value.
std::unique_ptr<Material> make_material(MaterialLaw law,
                                        const std::map<std::string, double>& params,
                                        const std::string& where);

}  // namespace valsalva::structure
