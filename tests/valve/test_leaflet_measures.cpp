// Mid-surface, crossing and coaptation measures between leaflets (valve/leaflet_pairs.hpp) on
// flat plates whose answers are known exactly, and the leaflet-group checks.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>

#include "structure/mesh_generators.hpp"
#include "valve/leaflet_groups.hpp"
#include "valve/leaflet_pairs.hpp"
#include "valve/mid_surface.hpp"

using namespace valsalva;
using structure::Vec3;

namespace {

// A plate [0, 10] x [0, 4] (mm), thickness t along y' after `map`, as leaflet `k` of `mesh`:
// its own body (structure::append_body) with the leaflet groups as aliases of the block sides.
void add_plate(structure::SolidMesh& mesh, int k, const std::function<Vec3(const Vec3&)>& map) {
  const double t = 0.15e-3;
  structure::SolidMesh p = structure::structured_block(
      structure::HexOrder::q2, {5, 2, 1},
      [&](const Vec3& s) { return map(Vec3(10e-3 * s[0], 4e-3 * s[1], (s[2] - 0.5) * t)); });
  for (auto [side, group] : {std::pair{"v0", "attachment"}, std::pair{"v1", "free_edge"},
                             std::pair{"w1", "aortic_face"}, std::pair{"w0", "ventricular_face"}})
    structure::alias_sets(p, side, group);
  const std::string name = "leaflet" + std::to_string(k);
  const int first = mesh.num_nodes();
  structure::append_body(mesh, p, name + "_");
  auto& all = mesh.node_sets[name];  // every node of the leaflet
  for (int n = first; n < mesh.num_nodes(); ++n) all.push_back(n);
}

structure::ValveFrame frame() {
  structure::ValveFrame v;
  v.annulus_radius = 1e-2;
  v.axis = Vec3::UnitY();  // plates extend 4 mm along the axis
  return v;
}

}  // namespace

TEST_CASE("closest point and segment crossing on one triangle") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  CHECK((valve::closest_point_on_triangle(Vec3(0.2, 0.2, 3), a, b, c) - Vec3(0.2, 0.2, 0)).norm() ==
        doctest::Approx(0).epsilon(1e-15));
  CHECK((valve::closest_point_on_triangle(Vec3(2, 2, 0), a, b, c) - Vec3(0.5, 0.5, 0)).norm() ==
        doctest::Approx(0).scale(1));
  CHECK(valve::segment_crosses_triangle(Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), a, b, c));
  CHECK_FALSE(valve::segment_crosses_triangle(Vec3(0.8, 0.8, -1), Vec3(0.8, 0.8, 1), a, b, c));
  CHECK_FALSE(valve::segment_crosses_triangle(Vec3(0.2, 0.2, 0.5), Vec3(0.2, 0.2, 1), a, b, c));
}

TEST_CASE("leaflet pairs: parallel plates a gap apart, and plates crossing") {
  const double gap = 0.4e-3;
  structure::SolidMesh parallel;
  add_plate(parallel, 1, [](const Vec3& p) { return Vec3(p.x(), p.y(), p.z()); });
  add_plate(parallel, 2, [&](const Vec3& p) { return Vec3(p.x(), p.y(), p.z() + gap); });
  const auto groups = valve::leaflet_groups(parallel);
  REQUIRE(groups.size() == 2);
  auto r = valve::leaflet_pairs(parallel, parallel.X, groups, frame(), 1.5 * gap);
  CHECK(r.crossings == 0);
  CHECK(r.min_distance == doctest::Approx(gap).epsilon(1e-9));
  // Every point is within the distance: the band is the plates' whole extent along the axis.
  CHECK(r.coaptation_height == doctest::Approx(4e-3).epsilon(1e-9));
  r = valve::leaflet_pairs(parallel, parallel.X, groups, frame(), 0.5 * gap);
  CHECK(r.coaptation_height == 0);

  // The second plate tilted through the first along the line x = 5.1 mm.
  structure::SolidMesh crossing;
  add_plate(crossing, 1, [](const Vec3& p) { return p; });
  add_plate(crossing, 2,
            [](const Vec3& p) { return Vec3(p.x(), p.y(), 0.1 * (p.x() - 5.1e-3) + p.z()); });
  r = valve::leaflet_pairs(crossing, crossing.X, valve::leaflet_groups(crossing), frame(), 1e-4);
  CHECK(r.crossings > 0);
  CHECK(r.min_distance < 1e-12);
}

TEST_CASE("leaflet groups: a missing group is named") {
  structure::SolidMesh m;
  add_plate(m, 1, [](const Vec3& p) { return p; });
  m.source = "plates.msh";
  m.surface_sets.erase("leaflet1_aortic_face");
  CHECK_THROWS_WITH(valve::leaflet_groups(m),
                    doctest::Contains("plates.msh: physical surface 'leaflet1_aortic_face'"));
  structure::SolidMesh none;
  none.source = "empty.msh";
  CHECK_THROWS_WITH(valve::leaflet_groups(none), doctest::Contains("empty.msh: no leaflets"));
}
