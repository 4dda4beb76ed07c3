#include "les/pope_estimate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace valsalva::les {

double pope_subgrid_fraction(double delta, double integral_length, double c) {
  if (!(delta > 0.0) || !(integral_length > 0.0) || !(c > 0.0))
    throw std::invalid_argument(
        fmt::format("pope_subgrid_fraction: Delta = {}, L = {}, C = {} must all be > 0", delta,
                    integral_length, c));
  return 1.5 * c * std::cbrt(std::pow(delta / (std::numbers::pi * integral_length), 2));
}

double pope_filter_width(double subgrid_fraction, double integral_length, double c) {
  if (!(subgrid_fraction > 0.0) || !(integral_length > 0.0) || !(c > 0.0))
    throw std::invalid_argument(
        fmt::format("pope_filter_width: fraction = {}, L = {}, C = {} must all be > 0",
                    subgrid_fraction, integral_length, c));
  return std::numbers::pi * integral_length * std::pow(subgrid_fraction / (1.5 * c), 1.5);
}

}  // namespace valsalva::les
