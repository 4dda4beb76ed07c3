// Rescales a velocity field on a periodic n^3 box (layout in fft_box.hpp) so that its shell
// spectrum equals a prescribed E(k) on shells s = 1 .. n/2 - 1 and is zero elsewhere, keeping
// every mode's phase and direction (u_hat(k) *= sqrt(E(k_s) dk / E_s dk) per shell s).
// Used to give a random-phase initial field the phase correlations of developed turbulence:
// run the flow and rescale back to the target spectrum after every step for about one eddy
// turnover (the "iterative rescaling" spin-up of decaying-turbulence LES, e.g. Kang, Chester &
// Meneveau, J. Fluid Mech. 480, 2003), so that energy transfer exists from the first step on.
#pragma once

#include <functional>
#include <span>

namespace valsalva::les {

// Throws std::invalid_argument for wrong sizes, and when a shell to fill has no energy.
void rescale_to_spectrum(const std::function<double(double)>& spectrum, int n, double length,
                         std::span<double> u, std::span<double> v, std::span<double> w);

}  // namespace valsalva::les
