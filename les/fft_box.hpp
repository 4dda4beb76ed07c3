// Real-to-complex 3D FFT of one scalar field on a periodic structured n^3 box of side L (FFTW).
//
// Layout (shared by all spectral tools in les/): node (i, j, k) at x = (i, j, k) L / n is stored
// at index (k n + j) n + i, x fastest. The half spectrum has n x n x (n/2 + 1) modes, index
// (c n + b)(n/2 + 1) + a for wavenumber (m_x, m_y, m_z) = (a, signed(b), signed(c)) 2 pi / L.
// forward() divides by n^3, so the coefficients are Fourier amplitudes: u = sum u_hat e^{i k.x}.
#pragma once

#include <complex>
#include <cstddef>
#include <span>

namespace valsalva::les {

class FftBox {
 public:
  explicit FftBox(int n);
  ~FftBox();
  FftBox(const FftBox&) = delete;
  FftBox& operator=(const FftBox&) = delete;

  int n() const { return n_; }
  int nx_half() const { return n_ / 2 + 1; }
  std::size_t real_size() const;
  std::size_t spectral_size() const;

  std::span<double> real() { return {real_, real_size()}; }
  std::span<std::complex<double>> spectrum() { return {spec_, spectral_size()}; }

  void forward();   // real() -> spectrum(), normalised by 1/n^3
  void backward();  // spectrum() -> real(), no normalisation (inverse of forward); keeps spectrum()

  // Signed integer wavenumber of index i along y or z: i for i <= n/2, i - n above.
  int signed_index(int i) const { return i <= n_ / 2 ? i : i - n_; }
  // Multiplicity of a half-spectrum mode in the full spectrum (1 on the a = 0 and a = n/2
  // planes, whose conjugate partners are stored too, else 2).
  double multiplicity(int a) const { return (a == 0 || 2 * a == n_) ? 1.0 : 2.0; }

 private:
  int n_;
  double* real_ = nullptr;
  std::complex<double>* spec_ = nullptr;
  std::complex<double>* scratch_ = nullptr;  // c2r destroys its input
  void* plan_forward_ = nullptr;
  void* plan_backward_ = nullptr;
  void allocate_and_plan();
  void release();
};

// Calls f(index, mx, my, mz, multiplicity) for every stored mode (integer wavenumbers).
template <class F>
void for_each_mode(const FftBox& box, F&& f) {
  const int n = box.n(), nh = box.nx_half();
  std::size_t idx = 0;
  for (int c = 0; c < n; ++c)
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < nh; ++a, ++idx)
        f(idx, a, box.signed_index(b), box.signed_index(c), box.multiplicity(a));
}

// Checks that three fields have n^3 values each; throws std::invalid_argument naming `what`.
void check_box_fields(const char* what, int n, std::size_t u, std::size_t v, std::size_t w);

}  // namespace valsalva::les
