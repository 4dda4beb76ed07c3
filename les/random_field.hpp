// Divergence-free random velocity field with a prescribed energy spectrum on a periodic n^3 box
// (layout in fft_box.hpp): isotropic-turbulence initial conditions.
//
// Method (fixed amplitude, random phase and direction; Rogallo, NASA TM-81315, 1981): for every
// mode with shell index s = round(|m|) in 1 .. n/2 - 1,
//   u_hat(k) = A_s P(k) r_hat(k) / |P(k) r_hat(k)|,   A_s^2 = 2 E(k_s) dk / M_s,
// where r_hat is the FFT of seeded Gaussian white noise (so u_hat(-k) = conj(u_hat(k)) holds by
// construction), P(k) = I - k k^T / |k|^2 the solenoidal projector and M_s the number of modes
// in shell s. Every mode carries exactly its share of E(k_s) dk, so the discrete spectrum
// (energy_spectrum.hpp) equals E(k_s) on those shells to round-off; the mean is zero and shells
// s = 0 and s >= n/2 (incomplete, Nyquist) are empty. Only phases and directions are random.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

namespace valsalva::les {

// Fills u, v, w (n^3 values each, m/s) for E(k) [m^3/s^2] of k [1/m] on a box of side L [m].
void random_solenoidal_field(const std::function<double(double)>& spectrum, int n, double length,
                             std::uint64_t seed, std::span<double> u, std::span<double> v,
                             std::span<double> w);

}  // namespace valsalva::les
