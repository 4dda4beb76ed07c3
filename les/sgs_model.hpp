// Choice of subgrid-scale model by name, its constant, and the array loop that fills nu_sgs at
// every node from the nodal velocity gradients (no allocation; kernels in sgs_kernels.hpp).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace valsalva::les {

// In the order of les.model's accepted names.
enum class SgsKind { none, sigma, wale, smagorinsky };

// "none", "sigma", "wale", "smagorinsky"; parse throws std::invalid_argument naming the accepted
// values.
const std::vector<std::string>& sgs_kind_names();
std::string to_string(SgsKind kind);
SgsKind parse_sgs_kind(std::string_view name);

// Default constants, with their sources:
// - sigma: C_sigma = 1.35, Nicoud et al., Phys. Fluids 23, 085106 (2011), Sec. III (calibrated on
//   the mean Smagorinsky dissipation in isotropic turbulence).
// - wale: C_w = 0.5. Nicoud & Ducros (1999) relate C_w^2 = 10.6 C_s^2 (same mean dissipation as
//   Smagorinsky in isotropic turbulence); 0.5 corresponds to C_s = 0.154 and is the value used for
//   decaying isotropic turbulence (0.325, i.e. C_s = 0.1, is common for channel flow).
// - smagorinsky: C_s = 0.17, Lilly's estimate (1/pi)(3 C_K / 2)^(-3/4) with the Kolmogorov
//   constant C_K = 1.5 (Lilly 1967; Pope, Turbulent Flows, 2000, eq. 13.128).
inline constexpr double default_c_sigma = 1.35;
inline constexpr double default_c_wale = 0.5;
inline constexpr double default_c_smagorinsky = 0.17;

// Lilly's Smagorinsky constant from the Kolmogorov constant (Pope 2000, eq. 13.128).
double lilly_smagorinsky_constant(double kolmogorov_constant);
// WALE constant giving the Smagorinsky mean dissipation: C_w = sqrt(10.6) C_s (Nicoud & Ducros
// 1999).
double wale_constant_from_smagorinsky(double c_s);

struct SgsModel {
  SgsKind kind = SgsKind::none;
  double constant = 0.0;  // C_sigma, C_w or C_s; unused for none
};

double default_constant(SgsKind kind);

// The model with the given constant, or its default without one. A given constant must be finite
// and > 0 (std::invalid_argument; ignored for none).
SgsModel make_sgs_model(SgsKind kind, std::optional<double> constant = {});

// Filter width Delta = cube root of the (dual) volume, per node.
void filter_width(std::span<const double> volume, std::span<double> delta);

// nu_sgs[i] = model(grad[i], delta[i]) for every node; sizes must agree (std::invalid_argument).
void compute_nu_sgs(const SgsModel& model, std::span<const Eigen::Matrix3d> grad,
                    std::span<const double> delta, std::span<double> nu_sgs);
// Same from a flat array of 9 values per node, row-major: g_ij = du_i/dx_j at grad[9 n + 3 i + j].
void compute_nu_sgs(const SgsModel& model, std::span<const double> grad_flat,
                    std::span<const double> delta, std::span<double> nu_sgs);

}  // namespace valsalva::les
