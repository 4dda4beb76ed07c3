#include "les/sgs_model.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/enum_names.hpp"
#include "les/sgs_kernels.hpp"

namespace valsalva::les {

double lilly_smagorinsky_constant(double kolmogorov_constant) {
  return std::pow(1.5 * kolmogorov_constant, -0.75) / std::numbers::pi;
}

double wale_constant_from_smagorinsky(double c_s) {
  return std::sqrt(10.6) * c_s;
}

constexpr core::EnumNames<SgsKind, 4> kKinds{{"none", "sigma", "wale", "smagorinsky"},
                                             "subgrid model"};
VALSALVA_ENUM_NAMES(SgsKind, kKinds, sgs_kind_names, to_string, parse_sgs_kind)

double default_constant(SgsKind kind) {
  switch (kind) {
    case SgsKind::sigma:
      return default_c_sigma;
    case SgsKind::wale:
      return default_c_wale;
    case SgsKind::smagorinsky:
      return default_c_smagorinsky;
    case SgsKind::none:
      return 0.0;
  }
  return 0.0;
}

SgsModel make_sgs_model(SgsKind kind, std::optional<double> constant) {
  SgsModel m;
  m.kind = kind;
  m.constant = default_constant(m.kind);
  if (constant && m.kind != SgsKind::none) {
    if (!(std::isfinite(*constant) && *constant > 0.0))
      throw std::invalid_argument(
          fmt::format("subgrid model '{}': constant must be finite and > 0, got {}",
                      to_string(kind), *constant));
    m.constant = *constant;
  }
  return m;
}

void filter_width(std::span<const double> volume, std::span<double> delta) {
  if (volume.size() != delta.size())
    throw std::invalid_argument(
        fmt::format("filter_width: {} volumes but {} outputs", volume.size(), delta.size()));
  for (std::size_t i = 0; i < volume.size(); ++i) delta[i] = std::cbrt(volume[i]);
}

namespace {
using RowMajor3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// One loop per model: the switch stays outside the node loop.
template <class GradAt>
void apply(const SgsModel& model, std::size_t n, GradAt grad_at, std::span<const double> delta,
           std::span<double> nu) {
  const double c = model.constant;
  switch (model.kind) {
    case SgsKind::sigma:
      for (std::size_t i = 0; i < n; ++i) nu[i] = sigma_nu(grad_at(i), delta[i], c);
      break;
    case SgsKind::wale:
      for (std::size_t i = 0; i < n; ++i) nu[i] = wale_nu(grad_at(i), delta[i], c);
      break;
    case SgsKind::smagorinsky:
      for (std::size_t i = 0; i < n; ++i) nu[i] = smagorinsky_nu(grad_at(i), delta[i], c);
      break;
    case SgsKind::none:
      for (double& v : nu) v = 0.0;
      break;
  }
}

void check_sizes(const SgsModel& model, std::size_t grads, std::size_t delta, std::size_t nu) {
  if (grads != delta || grads != nu)
    throw std::invalid_argument(
        fmt::format("compute_nu_sgs ({}): sizes differ: {} gradients, {} filter widths, {} outputs",
                    to_string(model.kind), grads, delta, nu));
}
}  // namespace

void compute_nu_sgs(const SgsModel& model, std::span<const Eigen::Matrix3d> grad,
                    std::span<const double> delta, std::span<double> nu_sgs) {
  check_sizes(model, grad.size(), delta.size(), nu_sgs.size());
  apply(
      model, grad.size(), [&](std::size_t i) -> const Eigen::Matrix3d& { return grad[i]; }, delta,
      nu_sgs);
}

void compute_nu_sgs(const SgsModel& model, std::span<const double> grad_flat,
                    std::span<const double> delta, std::span<double> nu_sgs) {
  if (grad_flat.size() % 9 != 0)
    throw std::invalid_argument(
        fmt::format("compute_nu_sgs ({}): flat gradient array of {} values is not 9 per node",
                    to_string(model.kind), grad_flat.size()));
  const std::size_t n = grad_flat.size() / 9;
  check_sizes(model, n, delta.size(), nu_sgs.size());
  apply(
      model, n,
      [&](std::size_t i) {
        return Eigen::Matrix3d(Eigen::Map<const RowMajor3d>(&grad_flat[9 * i]));
      },
      delta, nu_sgs);
}

}  // namespace valsalva::les
