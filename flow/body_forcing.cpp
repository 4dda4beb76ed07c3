// Prescribed body forces; see body_forcing.hpp.
#include "flow/body_forcing.hpp"

#include <cmath>
#include <numbers>

namespace valsalva::flow {

Eigen::Vector3d ForcingSpec::uniform_force(double t) const {
  switch (waveform) {
    case Waveform::Kind::sine:
      return force + amplitude * std::sin(2 * std::numbers::pi * t / period + phase);
    case Waveform::Kind::table:
      return force * factor(t);
    case Waveform::Kind::constant:
      break;
  }
  return force;
}

bool ForcingSpec::time_dependent() const {
  return type == Type::flow_rate || (type == Type::uniform && waveform != Waveform::Kind::constant);
}

VectorField forcing_density(const mesh::LocalMesh& local, const ForcingSpec& spec) {
  VectorField f(local.num_local(), Eigen::Vector3d::Zero());
  if (spec.type == ForcingSpec::Type::uniform) {
    const Eigen::Vector3d f0 = spec.uniform_force(0.0);
    for (auto& v : f) v = f0;
  } else if (spec.type == ForcingSpec::Type::kolmogorov) {
    const double k = 2 * std::numbers::pi / spec.wavelength;
    const Eigen::Vector3d across = spec.across.normalized();
    Eigen::Vector3d net = Eigen::Vector3d::Zero();
    double volume = 0;
    for (int i = 0; i < local.num_local(); ++i) {
      f[i] = spec.force * std::sin(k * across.dot(local.position[i]));
      if (i < local.num_owned) net += local.volume[i] * f[i], volume += local.volume[i];
    }
    Eigen::Vector3d mean;
    for (int c = 0; c < 3; ++c) mean[c] = local.comm.sum(net[c]);
    mean /= local.comm.sum(volume);
    for (auto& v : f) v -= mean;
  }
  return f;
}

}  // namespace valsalva::flow
