#include "flow/patch_fluxes.hpp"

#include <mpi.h>

namespace valsalva::flow {

std::vector<double> patch_fluxes(const mesh::LocalMesh& mesh, const VectorField& u) {
  std::vector<double> flux(mesh.patch_names.size(), 0.0);
  for (const auto& b : mesh.boundary)
    if (b.node < mesh.num_owned) flux[b.patch] += u[b.node].dot(b.area);
  mesh.comm.sum_in_place(flux);
  return flux;
}

}  // namespace valsalva::flow
