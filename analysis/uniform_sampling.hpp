// Uniform sampling of a time series, for spectra: probe rows are written every N steps, and a run
// whose time step changes (adaptive dt, a restart with another dt) gives non-uniform sample times.
// check_sampling says whether the spacing is uniform to round-off (times carry 17 significant
// digits, so a relative spread of 1e-6 in the steps is far above the printing error and far
// below any real change of dt); resample_uniform interpolates linearly onto a uniform grid.
// Linear interpolation is a low-pass filter (amplitude response about sinc^2(f dt), 0.41 at the
// Nyquist frequency, 0.97 at fs / 10), so resampled spectra are attenuated towards fs / 2.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace valsalva::analysis {

struct Sampling {
  double dt_mean = 0, dt_min = 0, dt_max = 0;  // s
  bool uniform = false;                        // (dt_max - dt_min) <= tolerance dt_mean
};

// Throws std::invalid_argument, naming `what` and the sample, if there are fewer than 2 samples
// or the times are not finite and strictly increasing.
Sampling check_sampling(std::span<const double> time, const std::string& what,
                        double tolerance = 1e-6);

// `n` samples at time.front() + k (time.back() - time.front()) / (n - 1), linearly interpolated.
std::vector<double> resample_uniform(std::span<const double> time, std::span<const double> value,
                                     std::size_t n);

}  // namespace valsalva::analysis
