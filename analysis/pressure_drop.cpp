#include "analysis/pressure_drop.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace valsalva::analysis {

RegionMean::RegionMean(const mesh::LocalMesh& local, const Eigen::Vector3d& centre, double radius,
                       const std::string& what)
    : local_(&local) {
  double volume = 0;
  for (int i = 0; i < local.num_owned; ++i)
    if ((local.position[i] - centre).norm() <= radius) {
      nodes_.push_back(i);
      volume += local.volume[i];
    }
  volume_ = local.comm.sum(volume);
  global_nodes_ = local.comm.sum(static_cast<std::int64_t>(nodes_.size()));
  if (global_nodes_ == 0)
    throw std::runtime_error(
        fmt::format("{}: no mesh node within {} m of ({}, {}, {}) m: move the centre into the "
                    "fluid or enlarge the radius",
                    what, radius, centre.x(), centre.y(), centre.z()));
}

double RegionMean::operator()(const std::vector<double>& field) const {
  double s = 0;
  for (int i : nodes_) s += local_->volume[i] * field[i];
  return local_->comm.sum(s) / volume_;
}

}  // namespace valsalva::analysis
