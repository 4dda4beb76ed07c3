#include "mesh/metric_identities.hpp"

#include <cmath>

#include "core/compensated_sum.hpp"

namespace valsalva::mesh {

MetricIdentities measure_metric_identities(const LocalMesh& local, double mesh_volume_reference,
                                           const Eigen::Vector3d& g) {
  MetricIdentities out;
  core::CompensatedSum owned_volume;
  for (int i = 0; i < local.num_owned; ++i) owned_volume.add(local.volume[i]);
  out.volume_error = std::abs(local.comm.sum(owned_volume.value()) - mesh_volume_reference) /
                     mesh_volume_reference;

  std::vector<Eigen::Vector3d> closure(local.num_local(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> raw(local.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < local.num_owned_edges; ++e) {
    const auto [a, b] = local.edges[e];
    closure[a] += local.edge_normal[e];
    closure[b] -= local.edge_normal[e];
    const double dphi = g.dot(local.edge_vector[e]);  // phi_b - phi_a for phi = g.x
    raw[a] += 0.5 * dphi * local.edge_normal[e];
    raw[b] += 0.5 * dphi * local.edge_normal[e];
  }
  for (const auto& f : local.boundary) closure[f.node] += f.area;
  double closure_error = 0, gradient_error = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    closure_error = std::max(closure_error, closure[i].norm() / (local.h[i] * local.h[i]));
    const Eigen::Vector3d grad = local.gradient_correction[i] * raw[i] / local.volume[i];
    gradient_error = std::max(gradient_error, (grad - g).norm() / g.norm());
  }
  out.closure_error = local.comm.max(closure_error);
  out.gradient_error = local.comm.max(gradient_error);
  return out;
}

}  // namespace valsalva::mesh
