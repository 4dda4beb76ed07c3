// FFTW tools on a periodic box: energy spectrum (Parseval, shell binning), log-log spectrum
// table, divergence-free random fields with a prescribed spectrum.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "les/derivative_skewness.hpp"
#include "les/energy_spectrum.hpp"
#include "les/fft_box.hpp"
#include "les/random_field.hpp"
#include "les/spectrum_table.hpp"

using namespace valsalva::les;
constexpr double pi = std::numbers::pi;

namespace {
double half_mean_square(const std::vector<double>& u, const std::vector<double>& v,
                        const std::vector<double>& w) {
  double s = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) s += u[i] * u[i] + v[i] * v[i] + w[i] * w[i];
  return 0.5 * s / static_cast<double>(u.size());
}
std::size_t node(int n, int i, int j, int k) {
  return (std::size_t(k) * n + j) * n + i;
}
}  // namespace

TEST_CASE("FFT round trip and spectrum kept by backward()") {
  FftBox box(8);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> nd;
  std::vector<double> x(box.real_size());
  for (auto& xi : x) xi = nd(rng);
  std::copy(x.begin(), x.end(), box.real().begin());
  box.forward();
  const std::vector<std::complex<double>> hat(box.spectrum().begin(), box.spectrum().end());
  box.backward();
  double err = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) err = std::max(err, std::abs(box.real()[i] - x[i]));
  CHECK(err < 1e-14);
  CHECK(std::equal(hat.begin(), hat.end(), box.spectrum().begin()));
  CHECK_THROWS_AS(FftBox(7), std::invalid_argument);
}

TEST_CASE("energy spectrum: Parseval on a random (non-solenoidal) field") {
  const int n = 16;
  const double L = 0.3;
  std::mt19937_64 rng(2);
  std::normal_distribution<double> nd(0.5, 2.0);  // non-zero mean: the k = 0 shell counts too
  std::vector<double> u(n * n * n), v(u.size()), w(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = nd(rng), v[i] = nd(rng), w[i] = nd(rng);
  const EnergySpectrum s = energy_spectrum(u, v, w, n, L);
  CHECK(s.dk == doctest::Approx(2 * pi / L).epsilon(1e-15));
  const double ref = half_mean_square(u, v, w);
  MESSAGE("Parseval: sum E dk = " << s.total() << ", <u.u>/2 = " << ref);
  CHECK(std::abs(s.total() - ref) < 1e-13 * ref);
  std::vector<double> short_w(10);
  CHECK_THROWS_AS(energy_spectrum(u, v, short_w, n, L), std::invalid_argument);
}

TEST_CASE("energy spectrum: single Fourier modes land in their shells") {
  // u = A sin(3 * 2 pi x / L), v = B cos(2 pi (y + 2 z) / L): <u^2>/2 = A^2/4 in shell 3,
  // <v^2>/2 = B^2/4 in shell round(sqrt(5)) = 2.
  const int n = 16;
  const double L = 2.0, A = 1.5, B = 0.7;
  std::vector<double> u(n * n * n), v(u.size()), w(u.size(), 0.0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = i * L / n, y = j * L / n, z = k * L / n;
        u[node(n, i, j, k)] = A * std::sin(3 * 2 * pi * x / L);
        v[node(n, i, j, k)] = B * std::cos(2 * pi * (y + 2 * z) / L);
      }
  const EnergySpectrum s = energy_spectrum(u, v, w, n, L);
  CHECK(s.E[3] * s.dk == doctest::Approx(A * A / 4).epsilon(1e-13));
  CHECK(s.E[2] * s.dk == doctest::Approx(B * B / 4).epsilon(1e-13));
  double others = 0.0;
  for (std::size_t i = 0; i < s.E.size(); ++i)
    if (i != 2 && i != 3) others += s.E[i] * s.dk;
  CHECK(others < 1e-28);
  // div = du/dx + dv/dy: |div|^2 ~ 9 A^2 + B^2, |k|^2 |u_hat|^2 ~ 9 A^2 + 5 B^2 (common factors).
  CHECK(spectral_divergence_ratio(u, v, w, n, L) ==
        doctest::Approx(std::sqrt((9 * A * A + B * B) / (9 * A * A + 5 * B * B))).epsilon(1e-12));
}

TEST_CASE("spectrum table: log-log interpolation, extrapolation and errors") {
  const SpectrumTable t({1.0, 10.0, 100.0}, {1.0, 1e-2, 1e-5}, Extrapolation::none, "test");
  CHECK(t(10.0) == doctest::Approx(1e-2).epsilon(1e-14));
  CHECK(t(std::sqrt(10.0)) == doctest::Approx(0.1).epsilon(1e-14));  // k^-2 segment
  CHECK(t(std::sqrt(1000.0)) == doctest::Approx(1e-2 * std::pow(10.0, -1.5)).epsilon(1e-14));
  CHECK_THROWS_AS(t(0.5), std::out_of_range);
  const SpectrumTable p({1.0, 10.0, 100.0}, {1.0, 1e-2, 1e-5}, Extrapolation::power_law);
  CHECK(p(0.1) == doctest::Approx(100.0).epsilon(1e-13));
  CHECK(p(1000.0) == doctest::Approx(1e-8).epsilon(1e-13));
  CHECK_THROWS_AS(SpectrumTable({1.0, 1.0}, {1.0, 2.0}, Extrapolation::none),
                  std::invalid_argument);
  CHECK_THROWS_AS(SpectrumTable({1.0, 2.0}, {1.0, 0.0}, Extrapolation::none),
                  std::invalid_argument);
}

TEST_CASE("spectrum table: exact moments and large scales") {
  // Segments k^-2 on [1, 10] and 10 k^-3 on [10, 100]: hand-integrated moments.
  const SpectrumTable t({1.0, 10.0, 100.0}, {1.0, 1e-2, 1e-5}, Extrapolation::none, "test");
  CHECK(table_moment(t, 0.0) == doctest::Approx(0.9 + 0.0495).epsilon(1e-13));
  CHECK(table_moment(t, -1.0) ==
        doctest::Approx(0.495 + 10.0 / 3.0 * (1e-3 - 1e-6)).epsilon(1e-13));
  CHECK(table_moment(t, 1.0) == doctest::Approx(std::log(10.0) + 0.9).epsilon(1e-13));  // k^-1
  const LargeScales s = large_scales(t);
  const double u2 = 2.0 * 0.9495 / 3.0;
  CHECK(s.u_rms == doctest::Approx(std::sqrt(u2)).epsilon(1e-13));
  CHECK(s.integral_length == doctest::Approx(pi / (2 * u2) * table_moment(t, -1.0)).epsilon(1e-13));
  CHECK(s.turnover_time == doctest::Approx(s.integral_length / s.u_rms).epsilon(1e-14));
}

TEST_CASE("random solenoidal field: prescribed spectrum, zero divergence, isotropy, seeding") {
  // von Karman-Pao-like model spectrum, box of 2 pi: E = k^4 / (1 + k^2)^(17/6) (m^3/s^2).
  const int n = 32;
  const double L = 2 * pi;
  auto model = [](double k) { return std::pow(k, 4) / std::pow(1 + k * k, 17.0 / 6.0); };
  std::vector<double> u(n * n * n), v(u.size()), w(u.size());
  random_solenoidal_field(model, n, L, 42, u, v, w);
  const EnergySpectrum s = energy_spectrum(u, v, w, n, L);

  // Fixed amplitudes: every complete shell 1 .. n/2-1 carries E(k_s) to round-off; the others
  // are empty.
  double worst = 0.0, outside = 0.0, expected_total = 0.0;
  for (std::size_t i = 0; i < s.E.size(); ++i) {
    if (i >= 1 && i <= n / 2 - 1) {
      worst = std::max(worst, std::abs(s.E[i] / model(s.k[i]) - 1.0));
      expected_total += model(s.k[i]) * s.dk;
    } else {
      outside += s.E[i] * s.dk;
    }
  }
  const double div = spectral_divergence_ratio(u, v, w, n, L);
  MESSAGE("random field 32^3: max shell |E/E_model - 1| = "
          << worst << ", energy outside " << outside << ", divergence ratio " << div);
  CHECK(worst < 1e-12);
  CHECK(outside < 1e-15 * expected_total);
  CHECK(s.total() == doctest::Approx(expected_total).epsilon(1e-12));
  CHECK(div < 1e-14);

  // Isotropy: each component carries 1/3 of the energy on average over directions (the shells
  // are invariant under axis permutations). Per mode the share |e_x|^2 lies in [0, 1], variance
  // <= 1/4, and +/-k are one independent mode, so std(f_x) <= sqrt(sum_indep a^4 / 4) / sum a^2
  // with a the per-mode energy; 4 standard deviations bound the test.
  double bound = 0.0, sum = 0.0;
  {
    std::vector<int> count(n, 0);
    for (int c = 0; c < n; ++c)
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
          auto sg = [&](int i) { return i <= n / 2 ? i : i - n; };
          const int sh =
              int(std::lround(std::sqrt(double(sg(a) * sg(a) + sg(b) * sg(b) + sg(c) * sg(c)))));
          if (sh >= 1 && sh <= n / 2 - 1) ++count[sh];
        }
    for (int sh = 1; sh <= n / 2 - 1; ++sh) {
      const double a = model(sh * s.dk) * s.dk / count[sh];  // energy per mode
      bound += 0.5 * count[sh] * (2 * a) * (2 * a) / 4;      // count/2 independent pairs
      sum += count[sh] * a;
    }
  }
  const double sigma = std::sqrt(bound) / sum;
  double eu = 0, ev = 0, ew = 0;
  for (std::size_t i = 0; i < u.size(); ++i)
    eu += u[i] * u[i], ev += v[i] * v[i], ew += w[i] * w[i];
  const double et = eu + ev + ew;
  MESSAGE("component energy fractions " << eu / et << ", " << ev / et << ", " << ew / et
                                        << " (1/3 each; std bound " << sigma << ")");
  CHECK(std::abs(eu / et - 1.0 / 3) < 4 * sigma);
  CHECK(std::abs(ev / et - 1.0 / 3) < 4 * sigma);
  CHECK(std::abs(ew / et - 1.0 / 3) < 4 * sigma);

  // Same seed, same field; another seed, another field with the same spectrum.
  std::vector<double> u2(u.size()), v2(u.size()), w2(u.size());
  random_solenoidal_field(model, n, L, 42, u2, v2, w2);
  CHECK(u2 == u);
  random_solenoidal_field(model, n, L, 43, u2, v2, w2);
  CHECK(u2 != u);
  CHECK(energy_spectrum(u2, v2, w2, n, L).total() == doctest::Approx(s.total()).epsilon(1e-12));
}

TEST_CASE("gaussian random solenoidal field: spectrum within its chi^2 scatter") {
  // Shell energy / E(k_s) dk ~ chi^2_{2 M_s} / (2 M_s): z_s = (E_s / E - 1) sqrt(M_s) is close to
  // N(0, 1) (M_s >= 18 modes). Bounds: every |z_s| < 4.5 and sum z_s^2 within 4 standard
  // deviations of its chi^2_15 mean (15 +/- 4 sqrt(30)). Checked offline over 400 seeds at 16^3:
  // mean sum z^2 = 7.06 for 7 shells (variance 13.5, 14 expected).
  const int n = 32;
  const double L = 2 * pi;
  auto model = [](double k) { return std::pow(k, 4) / std::pow(1 + k * k, 17.0 / 6.0); };
  std::vector<double> u(n * n * n), v(u.size()), w(u.size());
  random_solenoidal_field(model, n, L, 7, u, v, w, Amplitudes::gaussian);
  const EnergySpectrum s = energy_spectrum(u, v, w, n, L);
  std::vector<int> count(n, 0);
  auto sg = [&](int i) { return i <= n / 2 ? i : i - n; };
  for (int c = 0; c < n; ++c)
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const int sh =
            int(std::lround(std::sqrt(double(sg(a) * sg(a) + sg(b) * sg(b) + sg(c) * sg(c)))));
        if (sh < n) ++count[sh];
      }
  double zmax = 0.0, chi2 = 0.0;
  for (int sh = 1; sh <= n / 2 - 1; ++sh) {
    const double z = (s.E[sh] / model(s.k[sh]) - 1.0) * std::sqrt(double(count[sh]));
    zmax = std::max(zmax, std::abs(z));
    chi2 += z * z;
  }
  const double div = spectral_divergence_ratio(u, v, w, n, L);
  MESSAGE("gaussian field 32^3: shell 1 has " << count[1] << " modes, max |z| = " << zmax
                                              << ", sum z^2 = " << chi2
                                              << " (15 expected), divergence ratio " << div);
  CHECK(count[1] == 18);
  CHECK(zmax < 4.5);
  CHECK(std::abs(chi2 - 15.0) < 4.0 * std::sqrt(30.0));
  CHECK(div < 1e-14);
  CHECK(s.E[0] * s.dk < 1e-30);
  CHECK(s.E[n / 2] * s.dk < 1e-30);
}

TEST_CASE("random solenoidal field: bad input is named") {
  std::vector<double> u(8 * 8 * 8), v(u.size()), w(u.size());
  auto bad = [](double k) { return k > 3.0 ? -1.0 : 1.0; };
  CHECK_THROWS_AS(random_solenoidal_field(bad, 8, 1.0, 1, u, v, w), std::invalid_argument);
  CHECK_THROWS_AS(random_solenoidal_field([](double) { return 1.0; }, 8, -1.0, 1, u, v, w),
                  std::invalid_argument);
}

TEST_CASE("derivative skewness: two-mode field against the hand-computed value, ~0 when Gaussian") {
  // u = sin(x) + (b/2) sin(2x), v = w = 0 on a box of side 2 pi: du/dx = cos x + b cos 2x, so
  // <g^3> = 3b/4 and <g^2> = (1 + b^2)/2 on the x component, 0 on the others; averaged over
  // the three components S = (b/4) / ((1 + b^2)/6)^(3/2).
  const int n = 16;
  const double L = 2 * pi, b = 0.6;
  std::vector<double> u(n * n * n), v(u.size(), 0.0), w(u.size(), 0.0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = i * L / n;
        u[node(n, i, j, k)] = std::sin(x) + 0.5 * b * std::sin(2 * x);
      }
  const double exact = (b / 4) / std::pow((1 + b * b) / 6, 1.5);
  CHECK(derivative_skewness(u, v, w, n, L) == doctest::Approx(exact).epsilon(1e-12));
  // Swapping the sign of the second mode flips the skewness.
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = i * L / n;
        u[node(n, i, j, k)] = std::sin(x) - 0.5 * b * std::sin(2 * x);
      }
  CHECK(derivative_skewness(u, v, w, n, L) == doctest::Approx(-exact).epsilon(1e-12));
  // A random-phase field has no triple correlations: S = 0 up to sampling scatter (~ sqrt(15 /
  // N) for N = 3 n^3 nearly independent gradient samples; measured 0.004 at n = 32).
  const int m = 32;
  std::vector<double> ur(m * m * m), vr(ur.size()), wr(ur.size());
  random_solenoidal_field([](double k) { return k * k * std::exp(-k / 4); }, m, L, 3, ur, vr, wr);
  CHECK(std::abs(derivative_skewness(ur, vr, wr, m, L)) < 0.05);
  std::vector<double> short_w(5);
  CHECK_THROWS_AS(derivative_skewness(u, v, short_w, n, L), std::invalid_argument);
}
