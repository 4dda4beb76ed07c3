// An LES model's eddy viscosity on a laminar validation flow: nu_sgs / nu of each step's last RK
// stage (run::RunLoop::subgrid_viscosity) over the owned nodes, a running max and sum, reduced
// over the ranks at the end.
#pragma once

#include <algorithm>

#include "mesh/local_mesh.hpp"

namespace valsalva::validation {

struct NuSgsStats {
  double max = 0, sum = 0, count = 0;
  // Nothing without a model (nu_sgs empty).
  void add(const mesh::LocalMesh& local, const std::vector<double>& nu_sgs, double nu) {
    if (nu_sgs.empty()) return;
    for (int j = 0; j < local.num_owned; ++j) {
      max = std::max(max, nu_sgs[j] / nu);
      sum += nu_sgs[j] / nu;
    }
    count += local.num_owned;
  }
  // Collective.
  double global_max(const mesh::LocalMesh& local) const { return local.comm.max(max); }
  double global_mean(const mesh::LocalMesh& local) const {
    return local.comm.sum(sum) / std::max(1.0, local.comm.sum(count));
  }
};

}  // namespace valsalva::validation
