// The subgrid viscosity the flow solver asks for at every RK stage: a model (SgsKind) and its
// constant (les/sgs_model.hpp) bound to the nodal filter widths of one mesh partition
// (Delta = cube root of the dual volume, handed in as a plain vector so that les/ never sees
// flow/ types). The flow solver wraps it in its callback; nothing here allocates per call.
//
// When nu_sgs is updated (SgsUpdate): at every RK stage (the model applied literally), or once
// per time step from v^n at the first stage and held over the other three. Holding it is common
// in LES codes (the eddy viscosity changes on the resolved time scale, and the RK4 step is
// limited to a fraction of it), and cuts the model's cost 4x; the effect on the results is
// measured in validation/tgv_les and noted in docs/scenes.md (les.update).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "les/sgs_model.hpp"

namespace valsalva::les {

enum class SgsUpdate { stage, step };

// "stage" or "step"; parse throws std::invalid_argument naming the accepted values.
const std::vector<std::string>& sgs_update_names();
std::string to_string(SgsUpdate update);
SgsUpdate parse_sgs_update(std::string_view name);

class SubgridViscosity {
 public:
  // `constant`: empty or <= 0 = the model's default (les/sgs_model.hpp). `filter_width`: Delta [m]
  // per node, > 0 and finite (std::invalid_argument naming the first bad node).
  SubgridViscosity(SgsKind kind, std::optional<double> constant, std::vector<double> filter_width,
                   SgsUpdate update = SgsUpdate::stage);

  // nu_sgs[i] [m^2/s] from the velocity gradient at node i (g_ij = du_i/dx_j); one gradient and
  // one output per filter width (std::invalid_argument otherwise).
  void operator()(std::span<const Eigen::Matrix3d> grad, std::span<double> nu_sgs) const;
  // Same from 9 row-major doubles per node.
  void operator()(std::span<const double> grad_flat, std::span<double> nu_sgs) const;
  // At RK stage `stage` (0..3): computes nu_sgs when the update policy asks for it, otherwise
  // leaves it as it is (the caller's array holds the values of stage 0). Returns whether it
  // computed.
  bool operator()(int stage, std::span<const Eigen::Matrix3d> grad, std::span<double> nu_sgs) const;
  bool updates_at(int stage) const { return update_ == SgsUpdate::stage || stage == 0; }
  SgsUpdate update() const { return update_; }

  const SgsModel& model() const { return model_; }
  bool active() const { return model_.kind != SgsKind::none; }
  std::size_t size() const { return delta_.size(); }
  std::span<const double> filter_width() const { return delta_; }

 private:
  SgsModel model_;
  std::vector<double> delta_;
  SgsUpdate update_;
};

}  // namespace valsalva::les
