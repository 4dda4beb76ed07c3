// The identities the node-centred finite-volume scheme rests on, measured on a distributed mesh
// (used by the mesh_metrics validation case and the MPI tests):
//   volume:   |sum of owned dual volumes - mesh volume| / mesh volume
//   closure:  max over owned nodes of |sum_k S_jk + sum A_j| / h_j^2
//   gradient: max over owned nodes of the relative error of the corrected Green-Gauss
//             gradient of the linear field g.x
#pragma once

#include "mesh/local_mesh.hpp"

namespace valsalva::mesh {

struct MetricIdentities {
  double volume_error = 0;
  double closure_error = 0;
  double gradient_error = 0;
};

// Collective over local.comm; `mesh_volume_reference` from mesh::mesh_volume.
MetricIdentities measure_metric_identities(const LocalMesh& local, double mesh_volume_reference,
                                           const Eigen::Vector3d& g = {0.3, -1.1, 2.4});

}  // namespace valsalva::mesh
