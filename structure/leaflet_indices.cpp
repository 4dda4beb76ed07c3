#include "structure/leaflet_indices.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace valsalva::structure {

std::vector<NodePosition> node_set_positions(const SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                                             const std::string& set, const ValveFrame& valve) {
  const ValveBasis b = valve_basis(valve);
  if (x.cols() != mesh.num_nodes())
    throw std::invalid_argument(fmt::format("solid mesh {}: {} positions for {} nodes", mesh.source,
                                            x.cols(), mesh.num_nodes()));
  std::vector<NodePosition> out;
  for (int n : mesh.node_set(set)) {
    const Vec3 local = b.to_local(x.col(n));
    out.push_back({n, x.col(n), std::hypot(local.x(), local.y()), local.z()});
  }
  return out;
}

StressSummary von_mises_summary(const NodalStress& stress, double p) {
  const Eigen::VectorXd& vm = stress.von_mises;
  if (!(p >= 0 && p <= 100))
    throw std::invalid_argument(fmt::format("von Mises summary: percentile {} not in [0, 100]", p));
  if (vm.size() == 0) throw std::invalid_argument("von Mises summary: no nodes");
  StressSummary s;
  s.nodes = int(vm.size());
  s.percentile = p;
  s.max = vm.maxCoeff(&s.max_node);
  std::vector<double> sorted(vm.data(), vm.data() + vm.size());
  std::sort(sorted.begin(), sorted.end());
  const double pos = (s.nodes - 1) * p / 100;
  const int lo = std::min(int(std::floor(pos)), s.nodes - 1), hi = std::min(lo + 1, s.nodes - 1);
  s.at_percentile = sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
  return s;
}

StressSummary von_mises_summary(const SolidForces& forces, const Eigen::Matrix3Xd& x, double p) {
  if (x.cols() != forces.mesh().num_nodes())
    throw std::invalid_argument(fmt::format("solid mesh {}: {} positions for {} nodes",
                                            forces.mesh().source, x.cols(),
                                            forces.mesh().num_nodes()));
  return von_mises_summary(nodal_stress(forces, x), p);
}

}  // namespace valsalva::structure
