// Test helpers: seeded random velocity gradients and rotations.
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <random>

namespace valsalva::les::test {

inline Eigen::Matrix3d gaussian_matrix(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Matrix3d a;
  for (int i = 0; i < 9; ++i) a.data()[i] = n(rng);
  return a;
}

// Random orthogonal matrix (Q factor of a Gaussian matrix).
inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  Eigen::HouseholderQR<Eigen::Matrix3d> qr(gaussian_matrix(rng));
  return qr.householderQ();
}

}  // namespace valsalva::les::test
