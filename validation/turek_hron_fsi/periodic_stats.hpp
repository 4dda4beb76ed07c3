// Mean, amplitude and frequency of a periodic time series, the Turek–Hron way: over the last
// full period, mean = (max + min) / 2 and amplitude = (max - min) / 2; the frequency from the
// upward crossings of the mid-range (linearly interpolated between samples), averaged over all
// full periods after t_from; also the spread of the amplitude from period to period.
#pragma once

#include <span>

namespace valsalva::validation {

struct PeriodicStats {
  int periods = 0;  // full periods found after t_from (0: not periodic there)
  double frequency = 0, mean = 0, amplitude = 0;
  double t0 = 0, t1 = 0;  // the last period
  // (max - min) / 2 of every full period after t_from: mean and standard deviation (how far the
  // state is from periodic).
  double amplitude_mean = 0, amplitude_std = 0;
};

// Crossings and the last period of `y`; `t` increasing, same length.
PeriodicStats periodic_stats(std::span<const double> t, std::span<const double> y, double t_from);

// Mean and amplitude of `y` over [t0, t1] (another signal over the period found above).
PeriodicStats window_stats(std::span<const double> t, std::span<const double> y, double t0,
                           double t1);

}  // namespace valsalva::validation
