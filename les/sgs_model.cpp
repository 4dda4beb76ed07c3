#include "les/sgs_model.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "les/sgs_kernels.hpp"

namespace valsalva::les {

double lilly_smagorinsky_constant(double kolmogorov_constant) {
  return std::pow(1.5 * kolmogorov_constant, -0.75) / std::numbers::pi;
}

double wale_constant_from_smagorinsky(double c_s) { return std::sqrt(10.6) * c_s; }

const char* name(SgsKind kind) {
  switch (kind) {
    case SgsKind::sigma: return "sigma";
    case SgsKind::wale: return "wale";
    case SgsKind::smagorinsky: return "smagorinsky";
    case SgsKind::none: return "none";
  }
  return "?";
}

double default_constant(SgsKind kind) {
  switch (kind) {
    case SgsKind::sigma: return default_c_sigma;
    case SgsKind::wale: return default_c_wale;
    case SgsKind::smagorinsky: return default_c_smagorinsky;
    case SgsKind::none: return 0.0;
  }
  return 0.0;
}

SgsModel make_sgs_model(std::string_view model_name, std::optional<double> constant) {
  SgsModel m;
  if (model_name == "sigma") m.kind = SgsKind::sigma;
  else if (model_name == "wale") m.kind = SgsKind::wale;
  else if (model_name == "smagorinsky") m.kind = SgsKind::smagorinsky;
  else if (model_name == "none") m.kind = SgsKind::none;
  else
    throw std::invalid_argument(fmt::format(
        "unknown subgrid model '{}'; accepted: sigma, wale, smagorinsky, none", model_name));
  m.constant = default_constant(m.kind);
  if (constant && m.kind != SgsKind::none) {
    if (!(std::isfinite(*constant) && *constant > 0.0))
      throw std::invalid_argument(fmt::format(
          "subgrid model '{}': constant must be finite and > 0, got {}", model_name, *constant));
    m.constant = *constant;
  }
  return m;
}

void filter_width(std::span<const double> volume, std::span<double> delta) {
  if (volume.size() != delta.size())
    throw std::invalid_argument(fmt::format("filter_width: {} volumes but {} outputs",
                                            volume.size(), delta.size()));
  for (std::size_t i = 0; i < volume.size(); ++i) delta[i] = std::cbrt(volume[i]);
}

namespace {
template <class Kernel>
void apply(Kernel kernel, double c, std::span<const Eigen::Matrix3d> grad,
           std::span<const double> delta, std::span<double> nu) {
  for (std::size_t i = 0; i < grad.size(); ++i) nu[i] = kernel(grad[i], delta[i], c);
}
}  // namespace

void compute_nu_sgs(const SgsModel& model, std::span<const Eigen::Matrix3d> grad,
                    std::span<const double> delta, std::span<double> nu_sgs) {
  if (grad.size() != delta.size() || grad.size() != nu_sgs.size())
    throw std::invalid_argument(fmt::format(
        "compute_nu_sgs ({}): sizes differ: {} gradients, {} filter widths, {} outputs",
        name(model.kind), grad.size(), delta.size(), nu_sgs.size()));
  switch (model.kind) {
    case SgsKind::sigma: apply(sigma_nu, model.constant, grad, delta, nu_sgs); break;
    case SgsKind::wale: apply(wale_nu, model.constant, grad, delta, nu_sgs); break;
    case SgsKind::smagorinsky: apply(smagorinsky_nu, model.constant, grad, delta, nu_sgs); break;
    case SgsKind::none:
      for (double& v : nu_sgs) v = 0.0;
      break;
  }
}

}  // namespace valsalva::les
