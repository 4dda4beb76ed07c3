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

namespace {

// Maximum (and its index) and the p-th percentile of `values`; `what` names them in errors.
StressSummary summarise(const Eigen::VectorXd& values, double p, const char* what) {
  if (!(p >= 0 && p <= 100))
    throw std::invalid_argument(fmt::format("von Mises summary: percentile {} not in [0, 100]", p));
  if (values.size() == 0)
    throw std::invalid_argument(fmt::format("von Mises summary: no {}", what));
  StressSummary s;
  s.samples = int(values.size());
  s.percentile = p;
  int at = 0;
  s.max = values.maxCoeff(&at);
  s.max_node = at;
  std::vector<double> sorted(values.data(), values.data() + values.size());
  std::sort(sorted.begin(), sorted.end());
  const double pos = (s.samples - 1) * p / 100;
  const int lo = std::min(int(std::floor(pos)), s.samples - 1),
            hi = std::min(lo + 1, s.samples - 1);
  s.at_percentile = sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
  return s;
}

}  // namespace

StressSummary von_mises_summary(const NodalStress& stress, double p) {
  return summarise(stress.von_mises, p, "nodes");
}

StressSummary von_mises_summary(const SolidForces& forces, const Eigen::Matrix3Xd& x, double p) {
  if (x.cols() != forces.mesh().num_nodes())
    throw std::invalid_argument(fmt::format("solid mesh {}: {} positions for {} nodes",
                                            forces.mesh().source, x.cols(),
                                            forces.mesh().num_nodes()));
  const GaussPointStress g = gauss_point_stress(forces, x);
  StressSummary s = summarise(g.von_mises, p, "Gauss points");
  const int point = s.max_node;
  s.max_node = -1;
  s.max_element = point / g.points_per_element;
  s.max_position = g.position.col(point);
  return s;
}

}  // namespace valsalva::structure
