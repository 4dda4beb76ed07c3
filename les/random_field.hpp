// Divergence-free random velocity field with a prescribed energy spectrum on a periodic n^3 box
// (layout in fft_box.hpp): isotropic-turbulence initial conditions.
//
// Method: r_hat = FFT of seeded Gaussian white noise (so u_hat(-k) = conj(u_hat(k)) holds by
// construction), P(k) = I - k k^T / |k|^2 the solenoidal projector, M_s the number of modes in
// shell s = round(|m|), A_s^2 = 2 E(k_s) dk / M_s. For every mode with s in 1 .. n/2 - 1:
// - fixed (default; random phase and direction, fixed amplitude as in Rogallo, NASA TM-81315,
//   1981): u_hat = A_s P r_hat / |P r_hat|. Every mode carries exactly its share of E(k_s) dk, so
//   the discrete spectrum (energy_spectrum.hpp) equals E(k_s) on those shells to round-off.
// - gaussian (a Gaussian random field): u_hat = A_s sqrt(n^3 / 2) P r_hat, so <|u_hat|^2> = A_s^2;
//   the shell energy is chi^2-distributed with 2 M_s degrees of freedom: relative standard
//   deviation 1 / sqrt(M_s) about E(k_s).
// The mean is zero and shells s = 0 and s >= n/2 (incomplete, Nyquist) are empty.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

namespace valsalva::les {

enum class Amplitudes { fixed, gaussian };

// Fills u, v, w (n^3 values each, m/s) for E(k) [m^3/s^2] of k [1/m] on a box of side L [m].
void random_solenoidal_field(const std::function<double(double)>& spectrum, int n, double length,
                             std::uint64_t seed, std::span<double> u, std::span<double> v,
                             std::span<double> w, Amplitudes amplitudes = Amplitudes::fixed);

}  // namespace valsalva::les
