// Velocity-derivative skewness of a periodic n^3 box field (layout in fft_box.hpp):
//   S = < (du_i/dx_i)^3 > / < (du_i/dx_i)^2 >^(3/2), averaged over i = x, y, z (no sum),
// derivatives taken spectrally. Developed turbulence has S ~ -0.4 to -0.5 (the sign of the
// energy cascade; Batchelor & Townsend 1947); a random-phase (Gaussian) field has S = 0.
#pragma once

#include <span>

namespace valsalva::les {

double derivative_skewness(std::span<const double> u, std::span<const double> v,
                           std::span<const double> w, int n, double length);

}  // namespace valsalva::les
