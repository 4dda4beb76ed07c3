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

double peskin4(double r) {
  const double a = std::abs(r);
  return a < 2.0 ? 0.25 * (1.0 + std::cos(0.5 * std::numbers::pi * a)) : 0.0;
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

double kernel_3d(const KernelShape& shape, const Eigen::Vector3d& y, double h) {
  const double a = shape.width * h / natural_width(shape.type);
  return kernel_1d(shape.type, y.x() / a) * kernel_1d(shape.type, y.y() / a) *
         kernel_1d(shape.type, y.z() / a) / (a * a * a);
}

}  // namespace valsalva::ibm
