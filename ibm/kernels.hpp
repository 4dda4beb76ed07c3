// Base discrete Dirac kernels (1D, in grid units r = distance / spacing) and their tensor-product
// 3D form psi(y) dilated to a support `width * h` wide around a marker, h the local mesh size.
//  - Peskin 4-point cosine: phi(r) = (1 + cos(pi r / 2)) / 4 for |r| <= 2
//    (C. S. Peskin, "The immersed boundary method", Acta Numerica 11:479-517, 2002, section 6).
//  - Roma 3-point: (1 + sqrt(1 - 3 r^2)) / 3 for |r| <= 1/2, (5 - 3|r| - sqrt(1 - 3 (1 - |r|)^2)) /
//  6
//    for 1/2 <= |r| <= 3/2 (A. M. Roma, C. S. Peskin, M. J. Berger, J. Comput. Phys. 153:509-534,
//    1999).
//  - Cubic B-spline: 2/3 - r^2 + |r|^3 / 2 for |r| <= 1, (2 - |r|)^3 / 6 for 1 <= |r| <= 2
//    (the M4 spline of Monaghan, Annu. Rev. Astron. Astrophys. 30:543-574, 1992).
// Each integrates to one over its support. On an unstructured mesh none of them keeps its moments
// by itself: ibm/rkpm.hpp corrects them.
#pragma once

#include <Eigen/Dense>
#include <string_view>

namespace valsalva::ibm {

enum class KernelType { peskin4, roma3, bspline3 };

// "peskin4" | "roma3" | "bspline3"; throws std::invalid_argument naming the value otherwise.
KernelType parse_kernel_type(std::string_view name);
std::string_view kernel_name(KernelType type);

double peskin4(double r);
double roma3(double r);
double bspline3(double r);

// Width of the base kernel's support in grid units (4, 3, 4).
double natural_width(KernelType type);
double kernel_1d(KernelType type, double r);

struct KernelShape {
  KernelType type = KernelType::peskin4;
  double width = 4.0;  // support width in units of the local mesh size h (box of side width * h)
};

// Half-side of the support box around a marker of local mesh size h: width * h / 2.
double support_radius(const KernelShape& shape, double h);

// psi(y) = prod_d phi(y_d / a) / a^3 with a = width * h / natural_width, so that psi integrates
// to one and vanishes outside the box |y_d| < support_radius.
double kernel_3d(const KernelShape& shape, const Eigen::Vector3d& y, double h);

}  // namespace valsalva::ibm
