// The valve indices a run records ([valve] of a scene, scene/scene_keys_valve.cpp), carried out by
// valve::ValveMonitor (valve/valve_monitor.hpp).
#pragma once

#include <Eigen/Core>
#include <string>

namespace valsalva::analysis {

struct ValveMonitorOptions {
  std::string structure;  // the [structure.<name>] with node sets leaflet1..3; empty = none
  Eigen::Vector3d axis_point{0, 0, 0}, axis{0, 0, 1};  // the valve axis, flow towards +axis
  double annulus_radius = 0;                           // m, the disc of the orifice area
  Eigen::Vector3d tpg_upstream{0, 0, 0}, tpg_downstream{0, 0, 0};  // region centres, m
  double tpg_radius = 0;                                           // m
  std::string inlet_patch = "inlet", outlet_patch = "outlet";
  double period = 1, start_time = 0;  // s: the cycles of valve_cycles.csv
  double open_fraction = 0.05;        // of the cycle's largest opening: open / closed
  int every_steps = 1;
  int orifice_rings = 128;  // radial cells of the orifice area's polar grid
};

}  // namespace valsalva::analysis
