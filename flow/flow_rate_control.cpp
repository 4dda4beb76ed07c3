// Constant-flow-rate forcing; see flow_rate_control.hpp.
#include "flow/flow_rate_control.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace valsalva::flow {

FlowRateControl::FlowRateControl(const mesh::LocalMesh& local, BoundaryConditions* boundary,
                                 const ForcingSpec& spec, SectionFlux section_flux)
    : local_(local),
      spec_(spec),
      section_flux_(std::move(section_flux)),
      direction_(spec.direction.normalized()) {
  const int n = local.num_local();
  mask_.assign(n, direction_);
  if (boundary) {
    // The imposed values are affine in the field: impose(d) - impose(0) is the part of d the
    // boundary conditions let through.
    VectorField zero(n, Eigen::Vector3d::Zero());
    boundary->impose(mask_, 0.0);
    boundary->impose(zero, 0.0);
    for (int j = 0; j < n; ++j) mask_[j] -= zero[j];
  }
  central_face_flux(local, mask_, unit_flux_);
  response_ = section_flux_(unit_flux_);
  // The section's full area along d would be about sum |S_e . d|; a response far below it means
  // a section (nearly) parallel to d or wholly on walls.
  double area = 0;
  for (int e = 0; e < local.num_owned_edges; ++e)
    area = std::max(area, std::abs(local.edge_normal[e].dot(direction_)));
  area = local.comm.max(area);
  if (!(std::abs(response_) > 1e-9 * area))
    throw std::invalid_argument(fmt::format(
        "forcing.section: a uniform velocity along the direction ({:g}, {:g}, {:g}) moves no flux "
        "through section '{}' (response {:.3g} m^2): the section must cut the flow across that "
        "direction",
        direction_.x(), direction_.y(), direction_.z(), spec.section, response_));
}

void FlowRateControl::correct(VectorField& velocity, EdgeField& face_flux, double dt, double rho,
                              double time) {
  const double q = section_flux_(face_flux);
  const double du = (target(time) - q) / response_;
  for (std::size_t j = 0; j < velocity.size(); ++j) velocity[j] += du * mask_[j];
  for (std::size_t e = 0; e < face_flux.size(); ++e) face_flux[e] += du * unit_flux_[e];
  force_ += rho * du / dt;
}

void FlowRateControl::restore(const std::vector<double>& saved) {
  if (saved.size() != 1)
    throw std::invalid_argument(
        fmt::format("flow-rate control: a checkpoint state of {} values, expected 1 (the force)",
                    saved.size()));
  force_ = saved[0];
}

}  // namespace valsalva::flow
