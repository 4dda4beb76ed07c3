#include "analysis/welch_psd.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <memory>
#include <stdexcept>

namespace valsalva::analysis {

PowerSpectrum welch_psd(std::span<const double> signal, double sample_rate,
                        const WelchOptions& options) {
  const std::size_t n = options.segment_length;
  if (n < 2 || n > signal.size())
    throw std::invalid_argument(fmt::format(
        "welch_psd: segment_length = {} must be in [2, {}] (the signal length)", n, signal.size()));
  if (!(options.overlap >= 0 && options.overlap < 1))
    throw std::invalid_argument(
        fmt::format("welch_psd: overlap = {} must be in [0, 1)", options.overlap));
  if (!(sample_rate > 0))
    throw std::invalid_argument(fmt::format("welch_psd: sample_rate = {} Hz", sample_rate));
  const auto step = std::max<std::size_t>(1, n - std::size_t(std::llround(options.overlap * n)));

  // Periodic Hann window (the DFT-even form used for spectral estimation).
  std::vector<double> window(n);
  double window_power = 0;
  for (std::size_t i = 0; i < n; ++i) {
    window[i] = 0.5 * (1 - std::cos(2 * M_PI * double(i) / double(n)));
    window_power += window[i] * window[i];
  }

  const std::size_t bins = n / 2 + 1;
  std::vector<double> in(n);
  std::vector<std::complex<double>> out(bins);
  using Plan = std::unique_ptr<std::remove_pointer_t<fftw_plan>, decltype(&fftw_destroy_plan)>;
  Plan plan(fftw_plan_dft_r2c_1d(static_cast<int>(n), in.data(),
                                 reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE),
            &fftw_destroy_plan);
  if (!plan) throw std::runtime_error("welch_psd: FFTW could not make a plan");

  PowerSpectrum s;
  s.psd.assign(bins, 0.0);
  for (std::size_t start = 0; start + n <= signal.size(); start += step) {
    double mean = 0;
    for (std::size_t i = 0; i < n; ++i) mean += signal[start + i];
    mean /= double(n);
    for (std::size_t i = 0; i < n; ++i) in[i] = (signal[start + i] - mean) * window[i];
    fftw_execute(plan.get());
    for (std::size_t k = 0; k < bins; ++k) s.psd[k] += std::norm(out[k]);
    ++s.segments;
  }
  // Density scaling; interior bins doubled for the one-sided spectrum (not DC, not Nyquist).
  const double scale = 1.0 / (sample_rate * window_power * s.segments);
  for (std::size_t k = 0; k < bins; ++k) {
    const bool paired = k > 0 && !(n % 2 == 0 && k == n / 2);
    s.psd[k] *= scale * (paired ? 2.0 : 1.0);
  }
  s.df = sample_rate / double(n);
  for (std::size_t k = 0; k < bins; ++k) s.frequency.push_back(s.df * double(k));
  return s;
}

double spectrum_variance(const PowerSpectrum& spectrum) {
  double v = 0;
  for (double p : spectrum.psd) v += p * spectrum.df;
  return v;
}

}  // namespace valsalva::analysis
