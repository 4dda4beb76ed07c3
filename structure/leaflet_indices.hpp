// Leaflet indices besides the orifice area: positions of a named node set (e.g. the free-edge
// midpoint, the leaflet tip) relative to the valve axis, and a von Mises stress summary over
// Gauss points or nodes (structure/stress_recovery.hpp).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "structure/solid_forces.hpp"
#include "structure/stress_recovery.hpp"
#include "structure/valve_frame.hpp"

namespace valsalva::structure {

struct NodePosition {
  int node = -1;
  Vec3 position = Vec3::Zero();  // current position [m]
  double radial = 0;             // distance from the valve axis [m]
  double axial = 0;              // coordinate along the unit axis from valve.point [m]
};

// One entry per node of `set`, in the set's order. Throws std::invalid_argument for an unknown
// set (naming the known ones), a bad valve frame, or positions that do not match the mesh.
std::vector<NodePosition> node_set_positions(const SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                                             const std::string& set, const ValveFrame& valve);

struct StressSummary {
  double max = 0;                    // largest von Mises stress [Pa]
  int max_node = -1;                 // where, for a summary over nodes (else -1)
  int max_element = -1;              // where, for a summary over Gauss points (else -1)
  Vec3 max_position = Vec3::Zero();  // where, for a summary over Gauss points [m]
  double percentile = 0;             // the requested percentile p in [0, 100]
  double at_percentile = 0;          // its value [Pa]
  int samples = 0;                   // nodes or Gauss points summarised
};

// Percentile of the nodal values by linear interpolation between order statistics, position
// (n - 1) p / 100 in the sorted list (Hyndman & Fan, Am. Stat. 50(4), 1996, definition 7; the
// default of numpy.percentile). Throws for p outside [0, 100] or no nodes.
StressSummary von_mises_summary(const NodalStress& stress, double percentile);
// The same over the Gauss points (gauss_point_stress) at positions x of the mesh `forces` was
// built on: the summary the reports use, since a nodal value at a degenerate corner is not.
StressSummary von_mises_summary(const SolidForces& forces, const Eigen::Matrix3Xd& x,
                                double percentile);

}  // namespace valsalva::structure
