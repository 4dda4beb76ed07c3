// The resolved turbulent energy per unit mass at every owned node, for the output field
// sgs_energy_fraction (les/sgs_energy.hpp; output.fields with an [les] model):
// - at a node covered by a [statistics.<name>] section (the first that covers it), whose phase
//   bin of `time` holds at least 2 samples: the statistics' k / rho = (u'^2 + v'^2 + w'^2) / 2,
//   the energy of the fluctuations about the phase (or time) mean;
// - elsewhere the instantaneous |u|^2 / 2. It holds the mean flow's energy as well, so there the
//   fraction is a lower bound of the subgrid share of the turbulent energy (exact for flows
//   with zero mean, such as decaying isotropic turbulence in a periodic box).
#pragma once

#include <vector>

#include "analysis/phase_statistics.hpp"
#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::analysis {

// k[i] for the owned nodes (ghost entries 0), m^2/s^2; k is resized to the local node count.
void resolved_turbulent_energy(const mesh::LocalMesh& local, const flow::VectorField& velocity,
                               const std::vector<PhaseStatistics>& statistics, double time,
                               std::vector<double>& k);

}  // namespace valsalva::analysis
