// Power spectral density by Welch's method: the signal is cut into overlapping segments, each
// segment has its mean removed and is multiplied by a periodic Hann window, and the squared
// FFT magnitudes are averaged. One-sided density scaling (units^2 / Hz): the sum of psd * df
// equals the window-weighted mean square of the detrended segments, i.e. the variance of a
// stationary signal (Parseval). P. D. Welch, "The use of fast Fourier transform for the
// estimation of power spectra", IEEE Trans. Audio Electroacoustics 15(2), 70-73, 1967; the
// scaling is that of scipy.signal.welch(scaling='density', detrend='constant').
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace valsalva::analysis {

struct WelchOptions {
  std::size_t segment_length = 256;  // samples per segment (>= 2, <= signal length)
  double overlap = 0.5;              // fraction of a segment shared with the next, [0, 1)
};

struct PowerSpectrum {
  std::vector<double> frequency;  // Hz, k fs / segment_length, k = 0 .. segment_length / 2
  std::vector<double> psd;        // one-sided, units^2 / Hz
  int segments = 0;
  double df = 0;  // frequency resolution, Hz
};

// Throws std::invalid_argument naming the bad option. `sample_rate` in Hz.
PowerSpectrum welch_psd(std::span<const double> signal, double sample_rate,
                        const WelchOptions& options = {});

// Sum of psd * df: the variance the spectrum carries.
double spectrum_variance(const PowerSpectrum& spectrum);

}  // namespace valsalva::analysis
