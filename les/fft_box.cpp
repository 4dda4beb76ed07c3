#include "les/fft_box.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace valsalva::les {

FftBox::FftBox(int n) : n_(n) {
  if (n < 2 || n % 2 != 0)
    throw std::invalid_argument(fmt::format("FftBox: n must be even and >= 2, got {}", n));
  try {
    allocate_and_plan();
  } catch (...) {
    release();
    throw;
  }
}

void FftBox::allocate_and_plan() {
  const int n = n_;
  real_ = fftw_alloc_real(real_size());
  spec_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(spectral_size()));
  scratch_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(spectral_size()));
  if (!real_ || !spec_ || !scratch_) throw std::bad_alloc();
  plan_forward_ =
      fftw_plan_dft_r2c_3d(n, n, n, real_, reinterpret_cast<fftw_complex*>(spec_), FFTW_ESTIMATE);
  plan_backward_ = fftw_plan_dft_c2r_3d(n, n, n, reinterpret_cast<fftw_complex*>(scratch_), real_,
                                        FFTW_ESTIMATE);
  if (!plan_forward_ || !plan_backward_)
    throw std::runtime_error(fmt::format("FftBox: FFTW could not plan a {}^3 transform", n));
}

FftBox::~FftBox() {
  release();
}

void FftBox::release() {
  if (plan_forward_) fftw_destroy_plan(static_cast<fftw_plan>(plan_forward_));
  if (plan_backward_) fftw_destroy_plan(static_cast<fftw_plan>(plan_backward_));
  fftw_free(real_);
  fftw_free(spec_);
  fftw_free(scratch_);
}

std::size_t FftBox::real_size() const {
  return static_cast<std::size_t>(n_) * n_ * n_;
}
std::size_t FftBox::spectral_size() const {
  return static_cast<std::size_t>(n_) * n_ * nx_half();
}

void FftBox::forward() {
  fftw_execute(static_cast<fftw_plan>(plan_forward_));
  const double scale = 1.0 / static_cast<double>(real_size());
  for (auto& c : spectrum()) c *= scale;
}

void FftBox::backward() {
  // c2r overwrites its input: transform a copy so that spectrum() stays intact.
  std::copy(spec_, spec_ + spectral_size(), scratch_);
  fftw_execute(static_cast<fftw_plan>(plan_backward_));
}

void check_box_fields(const char* what, int n, std::size_t u, std::size_t v, std::size_t w) {
  const std::size_t expected = static_cast<std::size_t>(n) * n * n;
  if (u != expected || v != expected || w != expected)
    throw std::invalid_argument(
        fmt::format("{}: each velocity component needs n^3 = {} values (n = {}), got {}, {}, {}",
                    what, expected, n, u, v, w));
}

}  // namespace valsalva::les
