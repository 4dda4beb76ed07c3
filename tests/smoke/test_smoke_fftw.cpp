// FFTW smoke test: the r2c transform of x_n = c + A cos(2 pi k0 n / N) has exactly two non-zero
// coefficients, X_0 = c N and X_k0 = A N / 2 (FFTW is unnormalised). Round-off of an FFT grows
// like eps log2(N) sum|x_n| ~ 1e-16 * 6 * 112 ~ 1e-13, so 1e-12 is a safe bound.
#include <doctest/doctest.h>
#include <fftw3.h>

#include <cmath>
#include <complex>
#include <numbers>

TEST_CASE("FFTW: r2c transform of a cosine gives the exact coefficient") {
  constexpr int n = 64, k0 = 5;
  constexpr double amplitude = 1.5, offset = 0.25;
  double* in = fftw_alloc_real(n);
  fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
  REQUIRE(plan != nullptr);
  for (int i = 0; i < n; ++i)
    in[i] = offset + amplitude * std::cos(2.0 * std::numbers::pi * k0 * i / n);
  fftw_execute(plan);
  double worst = 0.0;
  for (int k = 0; k <= n / 2; ++k) {
    const std::complex<double> expected = k == 0 ? offset * n : k == k0 ? amplitude * n / 2 : 0.0;
    worst = std::max(worst, std::abs(std::complex<double>(out[k][0], out[k][1]) - expected));
  }
  CHECK(out[k0][0] == doctest::Approx(amplitude * n / 2).epsilon(1e-14));
  CHECK(worst < 1e-12);
  fftw_destroy_plan(plan);
  fftw_free(in);
  fftw_free(out);
}
