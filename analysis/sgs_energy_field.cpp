// Resolved turbulent energy for sgs_energy_fraction; see sgs_energy_field.hpp.
#include "analysis/sgs_energy_field.hpp"

namespace valsalva::analysis {

void resolved_turbulent_energy(const mesh::LocalMesh& local, const flow::VectorField& velocity,
                               const std::vector<PhaseStatistics>& statistics, double time,
                               std::vector<double>& k) {
  k.assign(static_cast<std::size_t>(local.num_local()), 0.0);
  std::vector<char> covered(k.size(), 0);
  for (const auto& stats : statistics) {
    if (time < stats.options().start_time) continue;
    const int bin = stats.bin_of(time);
    if (stats.count(bin) < 2) continue;  // no fluctuation measured yet
    const auto& nodes = stats.nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto node = static_cast<std::size_t>(nodes[i]);
      if (covered[node]) continue;
      k[node] = stats.kinetic_energy(bin, static_cast<int>(i)) / stats.options().density;
      covered[node] = 1;
    }
  }
  for (int i = 0; i < local.num_owned; ++i)
    if (!covered[i]) k[i] = 0.5 * velocity[i].squaredNorm();
}

}  // namespace valsalva::analysis
