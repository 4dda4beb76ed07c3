// Test helper: several leaflet meshes with their current positions, viewed as the
// LeafletPositions list geometric_orifice_area takes.
#pragma once

#include <vector>

#include "structure/orifice_area.hpp"

namespace valsalva::structure::testing {

struct Leaflets {
  std::vector<SolidMesh> meshes;
  std::vector<Eigen::Matrix3Xd> x;
  std::vector<LeafletPositions> view() const {
    std::vector<LeafletPositions> v;
    for (std::size_t i = 0; i < meshes.size(); ++i) v.push_back({&meshes[i], &x[i]});
    return v;
  }
  void add(SolidMesh m, Eigen::Matrix3Xd positions) {
    meshes.push_back(std::move(m));
    x.push_back(std::move(positions));
  }
  void add(SolidMesh m) {
    Eigen::Matrix3Xd X = m.X;
    add(std::move(m), std::move(X));
  }
};

inline OrificeArea area_of(const Leaflets& l, const ValveFrame& v, const OrificeOptions& o = {}) {
  const auto view = l.view();
  return geometric_orifice_area(view, v, o);
}

}  // namespace valsalva::structure::testing
