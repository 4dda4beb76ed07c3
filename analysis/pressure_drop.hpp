// The pressure difference between two regions of the fluid, e.g. the transvalvular pressure
// gradient of a valve (upstream in the left ventricular outflow, downstream in the ascending
// aorta), as PIV/catheter studies report it: mean pressure of each region (dual-volume weighted
// over the nodes inside a sphere) upstream minus downstream, in Pa and in mmHg
// (1 mmHg = 133.322387415 Pa, the conventional millimetre of mercury).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/local_mesh.hpp"

namespace valsalva::analysis {

inline constexpr double pascal_per_mmhg = 133.322387415;

class RegionMean {
 public:
  // Owned nodes within `radius` of `centre`. Collective; throws std::runtime_error naming the
  // region when it holds no node on any rank (`what` names it in the message).
  RegionMean(const mesh::LocalMesh& local, const Eigen::Vector3d& centre, double radius,
             const std::string& what);
  // Collective: dual-volume weighted mean of `field` over the region.
  double operator()(const std::vector<double>& field) const;
  std::int64_t nodes() const { return global_nodes_; }

 private:
  const mesh::LocalMesh* local_;
  std::vector<int> nodes_;
  double volume_ = 0;  // over all ranks
  std::int64_t global_nodes_ = 0;
};

struct PressureDrop {
  double upstream = 0, downstream = 0;  // Pa
  double mmhg() const { return (upstream - downstream) / pascal_per_mmhg; }
};

}  // namespace valsalva::analysis
