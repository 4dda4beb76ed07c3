// Measures between the leaflets of a valve, on their mid-surfaces (valve/mid_surface.hpp):
//  - crossings: pairs of mid-surface triangles of two different leaflets that intersect, i.e. a
//    leaflet passing through another (contact keeps the mid-surfaces a thickness apart);
//  - the smallest mid-surface distance between two leaflets (a thickness when they touch; 0
//    when they cross), from the mid-surface sample points to the other mid-surface;
//  - the coaptation height: the axial extent of the part of a leaflet's mid-surface that lies
//    within `coaptation_distance` of its neighbour's (the coapting band), largest over pairs.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "structure/solid_mesh.hpp"
#include "structure/valve_frame.hpp"
#include "valve/leaflet_groups.hpp"

namespace valsalva::valve {

struct LeafletPair {
  int a = 0, b = 0;              // leaflet indices (0-based)
  long crossings = 0;            // intersecting triangle pairs
  double min_distance = 0;       // smallest mid-surface distance [m]
  double coaptation_height = 0;  // [m], 0 when they do not come within the distance
  structure::Vec3 crossing_at = structure::Vec3::Zero();  // mean crossing point (valve axes:
                                                          // in-plane e1, e2, axial) if any
};

struct LeafletPairsReport {
  std::vector<LeafletPair> pairs;
  long crossings = 0;
  double min_distance = 0;
  double coaptation_height = 0;
};

// Whether some two leaflets' mid-surfaces intersect (the crossing test alone, for line searches).
bool leaflets_cross(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                    const std::vector<LeafletGroups>& leaflets);

LeafletPairsReport leaflet_pairs(const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                                 const std::vector<LeafletGroups>& leaflets,
                                 const structure::ValveFrame& valve, double coaptation_distance);

}  // namespace valsalva::valve
