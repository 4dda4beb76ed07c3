#include "les/subgrid_viscosity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/enum_names.hpp"

namespace valsalva::les {

constexpr core::EnumNames<SgsUpdate, 2> kUpdates{{"stage", "step"}, "subgrid update"};
VALSALVA_ENUM_NAMES(SgsUpdate, kUpdates, sgs_update_names, to_string, parse_sgs_update)

SubgridViscosity::SubgridViscosity(SgsKind kind, std::optional<double> constant,
                                   std::vector<double> filter_width, SgsUpdate update)
    : model_(
          make_sgs_model(kind, constant && *constant > 0.0 ? constant : std::optional<double>{})),
      delta_(std::move(filter_width)),
      update_(update) {
  for (std::size_t i = 0; i < delta_.size(); ++i)
    if (!(std::isfinite(delta_[i]) && delta_[i] > 0.0))
      throw std::invalid_argument(fmt::format(
          "subgrid viscosity ({}): filter width of node {} is {}, expected a finite value > 0",
          to_string(model_.kind), i, delta_[i]));
}

void SubgridViscosity::operator()(std::span<const Eigen::Matrix3d> grad,
                                  std::span<double> nu_sgs) const {
  compute_nu_sgs(model_, grad, delta_, nu_sgs);
}

void SubgridViscosity::operator()(std::span<const double> grad_flat,
                                  std::span<double> nu_sgs) const {
  compute_nu_sgs(model_, grad_flat, delta_, nu_sgs);
}

bool SubgridViscosity::operator()(int stage, std::span<const Eigen::Matrix3d> grad,
                                  std::span<double> nu_sgs) const {
  if (!updates_at(stage)) return false;
  compute_nu_sgs(model_, grad, delta_, nu_sgs);
  return true;
}

}  // namespace valsalva::les
