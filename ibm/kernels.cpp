#include "ibm/kernels.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace valsalva::ibm {

KernelType parse_kernel_type(std::string_view name) {
  if (name == "peskin4") return KernelType::peskin4;
  if (name == "roma3") return KernelType::roma3;
  if (name == "bspline3") return KernelType::bspline3;
  throw std::invalid_argument(fmt::format(
      "unknown kernel '{}': expected one of peskin4, roma3, bspline3", std::string(name)));
}

std::string_view kernel_name(KernelType type) {
  switch (type) {
    case KernelType::peskin4:
      return "peskin4";
    case KernelType::roma3:
      return "roma3";
    case KernelType::bspline3:
      return "bspline3";
  }
  return "?";
}

namespace {

// sin x for |x| <= pi/2 by its Taylor series to x^21 (truncation < 3e-16), evaluated in
// Horner form instead of std::cos (max difference 1.1e-16): DiracTransfer::locate, most of the
// coupling's cost, got 12 % faster (bench_ibm_transfer_cost, 4000 markers, width 4: 5.48 ->
// 4.81 us per marker). Coefficients (-1)^k / (2k + 1)!.
constexpr double kSinTaylor[11] = {
    1.00000000000000000e+00,  -1.66666666666666657e-01, 8.33333333333333322e-03,
    -1.98412698412698413e-04, 2.75573192239858925e-06,  -2.50521083854417202e-08,
    1.60590438368216133e-10,  -7.64716373181981641e-13, 2.81145725434552060e-15,
    -8.22063524662432950e-18, 1.95729410633912626e-20};

double sin_half_period(double x) {
  const double x2 = x * x;
  double p = kSinTaylor[10];
  for (int k = 9; k >= 0; --k) p = kSinTaylor[k] + x2 * p;
  return p * x;
}

}  // namespace

double peskin4(double r) {
  // (1 + cos(pi a / 2)) / 4 = (1 - sin(pi (a - 1) / 2)) / 4 for 0 <= a < 2.
  const double a = std::abs(r);
  return a < 2.0 ? 0.25 * (1.0 - sin_half_period(0.5 * std::numbers::pi * (a - 1.0))) : 0.0;
}

double roma3(double r) {
  const double a = std::abs(r);
  if (a <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0 * a * a)) / 3.0;
  if (a < 1.5) {
    const double b = 1.0 - a;
    return (5.0 - 3.0 * a - std::sqrt(1.0 - 3.0 * b * b)) / 6.0;
  }
  return 0.0;
}

double bspline3(double r) {
  const double a = std::abs(r);
  if (a <= 1.0) return 2.0 / 3.0 - a * a + 0.5 * a * a * a;
  if (a < 2.0) {
    const double b = 2.0 - a;
    return b * b * b / 6.0;
  }
  return 0.0;
}

double natural_width(KernelType type) {
  return type == KernelType::roma3 ? 3.0 : 4.0;
}

double kernel_1d(KernelType type, double r) {
  switch (type) {
    case KernelType::peskin4:
      return peskin4(r);
    case KernelType::roma3:
      return roma3(r);
    case KernelType::bspline3:
      return bspline3(r);
  }
  return 0.0;
}

double support_radius(const KernelShape& shape, double h) {
  return 0.5 * shape.width * h;
}

namespace {
template <double (*phi)(double)>
double tensor_product(const Eigen::Vector3d& y, double a) {
  return phi(y.x() / a) * phi(y.y() / a) * phi(y.z() / a) / (a * a * a);
}
}  // namespace

double kernel_3d(const KernelShape& shape, const Eigen::Vector3d& y, double h) {
  const double a = shape.width * h / natural_width(shape.type);
  // One dispatch per node rather than per factor: this runs for every node of every support.
  switch (shape.type) {
    case KernelType::peskin4:
      return tensor_product<peskin4>(y, a);
    case KernelType::roma3:
      return tensor_product<roma3>(y, a);
    case KernelType::bspline3:
      return tensor_product<bspline3>(y, a);
  }
  return 0.0;
}

}  // namespace valsalva::ibm
