#include "flow/patch_fluxes.hpp"

#include <mpi.h>

namespace valsalva::flow {

std::vector<double> patch_fluxes(const LocalMesh& mesh, const VectorField& u) {
  std::vector<double> flux(mesh.patch_names.size(), 0.0);
  for (const auto& b : mesh.boundary)
    if (b.node < mesh.num_owned) flux[b.patch] += u[b.node].dot(b.area);
  if (!flux.empty())
    VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, flux.data(), static_cast<int>(flux.size()), MPI_DOUBLE,
                               MPI_SUM, mesh.comm.get()));
  return flux;
}

}  // namespace valsalva::flow
