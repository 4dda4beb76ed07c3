// A random smooth divergence-free velocity field for energy checks (issue 21, target 2):
// u = U0 curl(phi A), A(x) = sum_m a_m sin(k_m . x + theta_m) with random amplitudes a_m,
// phases theta_m and whole-number wave vectors k_m = 2 pi (n_m / period), so that u is
// periodic over `period` along each axis. The envelope phi makes u vanish on a pipe's wall:
// with pipe_radius > 0, phi = (1 - r^2/R^2)^2 (4 s (1 - s))^2, r the distance from the z axis
// and s = z / pipe_length, so that u = phi curl A + grad phi x A is zero with phi and grad phi
// on r = R, z = 0 and z = length (no-slip walls all round); phi = 1 without it. Continuously
// divergence-free; the discrete field is projected by the first step like any start.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace valsalva::validation {

struct RandomSolenoidalSpec {
  double velocity = 1.0;                             // U0, m/s
  Eigen::Vector3d period = Eigen::Vector3d::Ones();  // m
  int modes = 24;                                    // number of modes of the vector potential
  int max_wavenumber = 1;  // |n_m| components in [-max_wavenumber, max_wavenumber], n_m != 0
  std::uint64_t seed = 1;  // the same seed gives the same field on every rank and platform
  double pipe_radius = 0;  // > 0: the pipe envelope (z axis, 0 <= z <= pipe_length)
  double pipe_length = 0;
};

class RandomSolenoidal {
 public:
  explicit RandomSolenoidal(const RandomSolenoidalSpec& spec);
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const;

 private:
  struct Mode {
    Eigen::Vector3d k, a;
    double phase;
  };
  RandomSolenoidalSpec spec_;
  std::vector<Mode> modes_;
  double scale_;  // U0 / (max |k| sqrt(modes)): a speed of order U0
};

}  // namespace valsalva::validation
