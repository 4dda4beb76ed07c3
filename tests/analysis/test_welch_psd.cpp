// Welch PSD: exact Parseval on one segment; a sine of amplitude A at f0 plus white noise of
// variance s^2 gives a peak at f0 holding A^2/2, a floor at 2 s^2/fs and a total of
// A^2/2 + s^2 (statistical tolerance: 2^17 samples -> relative scatter ~0.5%).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "analysis/welch_psd.hpp"

using namespace valsalva;

TEST_CASE("Welch PSD: Parseval on one segment") {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(1.0, 2.0);
  for (std::size_t n : {64, 99}) {  // even and odd lengths
    std::vector<double> x(n);
    for (auto& v : x) v = g(rng);
    const auto s = analysis::welch_psd(x, 50.0, {n, 0.5});
    CHECK(s.segments == 1);
    double mean = 0, wx2 = 0, w2 = 0;
    for (double v : x) mean += v / double(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 * (1 - std::cos(2 * M_PI * double(i) / double(n)));
      wx2 += (x[i] - mean) * (x[i] - mean) * w * w, w2 += w * w;
    }
    CHECK(analysis::spectrum_variance(s) == doctest::Approx(wx2 / w2).epsilon(1e-12));
  }
}

TEST_CASE("Welch PSD: sine plus white noise") {
  const double fs = 1000, amplitude = 2.0, f0 = 125.0, sigma = 0.5;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> x(1 << 17);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = 3.0 + amplitude * std::sin(2 * M_PI * f0 * double(i) / fs + 0.3) + noise(rng);
  const auto s = analysis::welch_psd(x, fs, {1024, 0.5});
  CHECK(s.segments == 255);
  CHECK(s.df == doctest::Approx(fs / 1024));
  CHECK(s.frequency.size() == 513);
  const auto peak = std::max_element(s.psd.begin(), s.psd.end()) - s.psd.begin();
  CHECK(s.frequency[peak] == doctest::Approx(f0));
  // Hann spreads a bin-centred sine over the peak and its two neighbours.
  double in_peak = 0;
  for (auto k = peak - 2; k <= peak + 2; ++k) in_peak += s.psd[k] * s.df;
  const double floor_level = 2 * sigma * sigma / fs;
  CHECK(in_peak ==
        doctest::Approx(amplitude * amplitude / 2 + 5 * floor_level * s.df).epsilon(0.01));
  std::vector<double> away(s.psd.begin() + 200, s.psd.end() - 1);
  double mean_floor = 0;
  for (double p : away) mean_floor += p / double(away.size());
  CHECK(mean_floor == doctest::Approx(floor_level).epsilon(0.03));
  CHECK(analysis::spectrum_variance(s) ==
        doctest::Approx(amplitude * amplitude / 2 + sigma * sigma).epsilon(0.01));
}

TEST_CASE("Welch PSD: bad options are named") {
  std::vector<double> x(100, 1.0);
  CHECK_THROWS_WITH(analysis::welch_psd(x, 10, {200, 0.5}),
                    doctest::Contains("segment_length = 200"));
  CHECK_THROWS_WITH(analysis::welch_psd(x, 10, {50, 1.0}), doctest::Contains("overlap = 1"));
  CHECK_THROWS_WITH(analysis::welch_psd(x, 0, {50, 0.5}), doctest::Contains("sample_rate = 0"));
}
