// Wall shear stress and its cycle statistics, the haemodynamic indices of vascular biomechanics:
//   tau_w        tangential part of the fluid's force on a wall node's dual face, per unit area
//                (flow::wall_loads: residual/reaction or surface-traction method)
//   TAWSS        (1/T) int |tau_w| dt
//   OSI          1/2 (1 - |int tau_w dt| / int |tau_w| dt)   (Ku, Giddens, Zarins & Glagov,
//                Arteriosclerosis 5, 1985): 0 for a steady direction, 1/2 for a purely
//                oscillatory stress.
//   RRT          1 / ((1 - 2 OSI) TAWSS) = T / |int tau_w dt|, the relative residence time
//                (Himburg et al., Am J Physiol Heart Circ Physiol 286, 2004, H1916), in 1/Pa.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "flow/wall_force.hpp"

namespace valsalva::flow {

// tau_j = (F_j - (F_j . n_j) n_j) / |A_j|, n_j = A_j / |A_j|, one per load (Pa).
std::vector<Eigen::Vector3d> wall_shear_stress(const std::vector<WallLoad>& loads);

// Time integrals of tau_w and |tau_w| at a fixed set of wall nodes (the nodes of the loads given
// to the first add()), by the trapezoidal rule over the intervals between samples: 2nd order on
// steps of any length (the rectangle rule it replaced was 1st order on varying steps: -0.38 % in
// the mean RRT of womersley_rheology), and exact for the mean of a periodic signal sampled
// uniformly over whole periods.
class WallShearStatistics {
 public:
  // One interval of length dt, tau_w at its start and at its end.
  void add(const std::vector<Eigen::Vector3d>& start, const std::vector<Eigen::Vector3d>& end,
           double dt);
  double duration() const { return duration_; }
  std::vector<double> tawss() const;
  std::vector<double> osi() const;  // 0 where tau_w was zero throughout
  // From the mean vector, not from TAWSS and OSI: no cancellation in 1 - 2 OSI. NaN where it is
  // undefined (infinite): the mean vector is zero (OSI = 1/2, or tau_w zero throughout) or
  // nothing was accumulated; NaN is what ParaView leaves out of colour ranges and pandas reads.
  std::vector<double> rrt() const;

  // Accumulators for checkpoints: per node sum tau dt (3) and sum |tau| dt (1), then duration.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

 private:
  std::vector<Eigen::Vector3d> sum_tau_;
  std::vector<double> sum_abs_;
  double duration_ = 0;
};

}  // namespace valsalva::flow
