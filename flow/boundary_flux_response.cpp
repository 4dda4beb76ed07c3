// The linear part of BoundaryConditions::impose() applied to a velocity change, as patch fluxes:
// what the lumped outlets' implicit coupling needs (flow/lumped_outlets.hpp). It mirrors
// impose() node by node, so that the flux it predicts is the flux impose() then makes.
#include <mpi.h>

#include "flow/boundary_conditions.hpp"

namespace valsalva::flow {

std::vector<double> BoundaryConditions::flux_response(const VectorField& du) {
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const bool held = role_[k] == Role::fixed || role_[k] == Role::inflow;
    response_[k] = held ? Eigen::Vector3d::Zero() : du[nodes_[k]];
    if (slip_[k]) remove_slip_normals(k, response_[k]);
  }
  // The mass correction of impose(), on the change alone.
  double sums[2] = {0, 0};
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    if (nodes_[k] >= mesh_.num_owned) continue;
    for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1]; ++i)
      sums[0] += response_[k].dot(mesh_.boundary[entries_[i]].area);
    if (free_outflow(k)) sums[1] += outlet_area_[k].squaredNorm();
  }
  mesh_.comm.sum_in_place(sums);
  if (sums[1] > 0)
    for (std::size_t k = 0; k < nodes_.size(); ++k)
      if (free_outflow(k)) response_[k] += (-sums[0] / sums[1]) * outlet_area_[k];
  std::vector<double> flux(patches_.size(), 0.0);
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    if (nodes_[k] >= mesh_.num_owned) continue;
    for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1]; ++i) {
      const auto& b = mesh_.boundary[entries_[i]];
      flux[b.patch] += response_[k].dot(b.area);
    }
  }
  mesh_.comm.sum_in_place(flux);
  return flux;
}

}  // namespace valsalva::flow
