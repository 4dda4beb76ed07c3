// See random_solenoidal.hpp.
#include "validation/inviscid_energy/random_solenoidal.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace valsalva::validation {

namespace {

// Uniform in [-1, 1) from the generator's bits: the same sequence on every standard library
// (std::uniform_real_distribution is implementation-defined).
double symmetric_unit(std::mt19937_64& rng) {
  return 2.0 * (rng() >> 11) * 0x1.0p-53 - 1.0;
}

}  // namespace

RandomSolenoidal::RandomSolenoidal(const RandomSolenoidalSpec& spec) : spec_(spec) {
  if (spec.modes < 1 || spec.max_wavenumber < 1 || !(spec.period.minCoeff() > 0))
    throw std::invalid_argument("random solenoidal field: modes, max_wavenumber and period > 0");
  std::mt19937_64 rng(spec.seed);
  const int nmax = spec.max_wavenumber, span = 2 * nmax + 1;
  double k_max = 0;
  while (static_cast<int>(modes_.size()) < spec.modes) {
    Eigen::Vector3d n;
    for (int d = 0; d < 3; ++d) n[d] = static_cast<double>(rng() % span) - nmax;
    if (n.squaredNorm() == 0) continue;
    Mode m;
    m.k = 2 * std::numbers::pi * n.cwiseQuotient(spec.period);
    m.a = {symmetric_unit(rng), symmetric_unit(rng), symmetric_unit(rng)};
    m.phase = std::numbers::pi * symmetric_unit(rng);
    k_max = std::max(k_max, m.k.norm());
    modes_.push_back(m);
  }
  scale_ = spec.velocity / (k_max * std::sqrt(static_cast<double>(spec.modes)));
}

Eigen::Vector3d RandomSolenoidal::operator()(const Eigen::Vector3d& x) const {
  Eigen::Vector3d potential = Eigen::Vector3d::Zero(), curl = Eigen::Vector3d::Zero();
  for (const auto& m : modes_) {
    const double arg = m.k.dot(x) + m.phase;
    potential += std::sin(arg) * m.a;
    curl += std::cos(arg) * m.k.cross(m.a);
  }
  if (!(spec_.pipe_radius > 0)) return scale_ * curl;
  const double R = spec_.pipe_radius, L = spec_.pipe_length;
  const double rho2 = (x.x() * x.x() + x.y() * x.y()) / (R * R), s = x.z() / L;
  if (rho2 >= 1 || s <= 0 || s >= 1) return Eigen::Vector3d::Zero();
  const double radial = (1 - rho2) * (1 - rho2), q = 4 * s * (1 - s), axial = q * q;
  // grad phi: d/dx (1 - r^2/R^2)^2 = -4 (1 - r^2/R^2) x / R^2; d/dz q^2 = 2 q 4 (1 - 2 s) / L.
  const Eigen::Vector3d grad_phi(-4 * (1 - rho2) * x.x() / (R * R) * axial,
                                 -4 * (1 - rho2) * x.y() / (R * R) * axial,
                                 radial * 8 * q * (1 - 2 * s) / L);
  return scale_ * (radial * axial * curl + grad_phi.cross(potential));
}

}  // namespace valsalva::validation
