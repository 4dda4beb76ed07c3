// The prescribed body force of a run loop ([forcing]): constant, time-dependent or held at a
// flow rate (flow/body_forcing.hpp, flow/flow_rate_control.hpp); see run_loop.hpp.
#include <fmt/format.h>

#include <algorithm>

#include "run/run_loop.hpp"

namespace valsalva::run {

void RunLoop::install_forcing() {
  const auto& spec = options_.forcing;
  if (spec.type == flow::ForcingSpec::Type::none) {
    if (options_.coupling.body_force) solver_.set_body_force(options_.coupling.body_force);
    return;
  }
  prescribed_force_ = std::make_shared<flow::VectorField>(flow::forcing_density(local_, spec));
  if (spec.type == flow::ForcingSpec::Type::flow_rate) {
    // The controller sets the flux of a domain closed by walls and periodic pairs.
    for (const auto& b : options_.boundary)
      if (b.type != flow::BoundaryType::wall && b.type != flow::BoundaryType::slip)
        throw RunError(fmt::format("forcing.type = flow_rate: boundary patch '{}' is not a wall "
                                   "or slip wall; the flow-rate control drives domains closed by "
                                   "walls and periodic pairs, whose flux nothing else sets",
                                   b.patch),
                       "forcing.type");
    if (!options_.section_flux)
      throw RunError("forcing.type = flow_rate needs the flux of its section (forcing.section)",
                     "forcing.section");
    try {
      flow_rate_control_ = std::make_shared<flow::FlowRateControl>(local_, boundary_.get(), spec,
                                                                   options_.section_flux);
    } catch (const std::invalid_argument& e) {
      throw RunError(e.what(), "forcing.section");
    }
  }
  // The stage's force: the field itself when it is constant (kolmogorov, a constant uniform
  // force), else the uniform value at the stage time or the controller's force of the step.
  auto prescribed = [spec, field = std::shared_ptr<const flow::VectorField>(prescribed_force_),
                     control = flow_rate_control_](double t, flow::VectorField& f) {
    if (spec.type == flow::ForcingSpec::Type::flow_rate)
      std::fill(f.begin(), f.end(), Eigen::Vector3d(control->force() * control->direction()));
    else if (spec.time_dependent())
      std::fill(f.begin(), f.end(), spec.uniform_force(t));
    else
      f = *field;
  };
  solver_.set_body_force([prescribed, coupled = options_.coupling.body_force,
                          own = std::make_shared<flow::VectorField>()](int stage, double t,
                                                                       const flow::VectorField& u,
                                                                       flow::VectorField& f) {
    if (!coupled) {
      prescribed(t, f);
      return;
    }
    coupled(stage, t, u, f);
    own->resize(f.size());
    prescribed(t, *own);
    for (std::size_t j = 0; j < f.size(); ++j) f[j] += (*own)[j];
  });
}

void RunLoop::update_forcing_field() {
  if (!prescribed_force_ || !options_.forcing.time_dependent()) return;
  const Eigen::Vector3d f =
      flow_rate_control_
          ? Eigen::Vector3d(flow_rate_control_->force() * flow_rate_control_->direction())
          : options_.forcing.uniform_force(state_.time);
  std::fill(prescribed_force_->begin(), prescribed_force_->end(), f);
}

std::vector<double> RunLoop::forcing_state() const {
  return flow_rate_control_ ? flow_rate_control_->saved() : std::vector<double>{};
}

void RunLoop::restore_forcing_state(const std::vector<double>& saved) {
  if (!flow_rate_control_) return;
  if (saved.empty())
    throw RunError(
        "flow run: the checkpoint has no flow-rate control state for forcing.type = "
        "flow_rate (written by a run without it)",
        "forcing.type");
  flow_rate_control_->restore(saved);
  update_forcing_field();
}

std::string RunLoop::forcing_log_header() const {
  const auto type = options_.forcing.type;
  std::string h;
  if (type == flow::ForcingSpec::Type::uniform || type == flow::ForcingSpec::Type::flow_rate)
    h = ",force_x,force_y,force_z";
  if (flow_rate_control_) h += ",flow_rate_target";
  return h;
}

std::string RunLoop::forcing_log_row() const {
  const auto type = options_.forcing.type;
  if (type != flow::ForcingSpec::Type::uniform && type != flow::ForcingSpec::Type::flow_rate)
    return {};
  // + 0.0: no "-0" in the log for a component the direction does not have.
  const Eigen::Vector3d f =
      (flow_rate_control_
           ? Eigen::Vector3d(flow_rate_control_->force() * flow_rate_control_->direction())
           : options_.forcing.uniform_force(state_.time))
          .array() +
      0.0;
  std::string row = fmt::format(",{:.17g},{:.17g},{:.17g}", f.x(), f.y(), f.z());
  if (flow_rate_control_) row += fmt::format(",{:.17g}", flow_rate_control_->target(state_.time));
  return row;
}

}  // namespace valsalva::run
