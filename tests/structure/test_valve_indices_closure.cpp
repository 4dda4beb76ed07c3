// Orifice area and tip position of the validation leaflet (validation/leaflet_closure) before
// and after its closure solve (about a minute, hence the validation label). Tolerances as in
// test_valve_indices.cpp: the library's raster error estimate plus the stated chord deficit.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>

#include "leaflet_set.hpp"
#include "structure/leaflet_indices.hpp"
#include "validation/leaflet_closure/leaflet_closure.hpp"

using namespace valsalva::structure;
using valsalva::structure::testing::area_of;
using valsalva::structure::testing::Leaflets;

TEST_CASE("orifice area: the leaflet_closure leaflet, open and closed") {
  // Three copies of the validation leaflet (128 Q2 elements) at 0, 120, 240 deg. Open (reference
  // configuration) they lie on the wall R +- t/2, so inside the disc they cover the band
  // R - t/2 .. R: opening ratio 1 - (t/R - t^2/(4 R^2)) exactly, up to the raster error and the
  // chord deficit of the faces, 3 x 16 elements x 4 chords around: (2 pi / 192)^2 / 6 = 1.8e-4 of
  // the disc. Closed, they fold towards the axis and the area must shrink.
  const auto c = valsalva::validation::close_leaflet(false, 300.0, false);
  REQUIRE(c.result.converged);
  const double Rv = c.geometry.radius, t = c.geometry.thickness;
  ValveFrame v;
  v.annulus_radius = Rv;
  Leaflets open, closed;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Matrix3d rot =
        Eigen::AngleAxisd(2 * M_PI * k / 3, Vec3::UnitZ()).toRotationMatrix();
    open.add(c.mesh, rot * c.mesh.X);
    closed.add(c.mesh, rot * c.result.x);
  }
  const OrificeArea ao = area_of(open, v);
  const auto t0 = std::chrono::steady_clock::now();
  const OrificeArea ac = area_of(closed, v);
  MESSAGE("orifice area of 3 x 128 Q2 elements, "
          << ac.triangles << " triangles, " << ac.rings << " x " << ac.sectors << " cells: "
          << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s");
  MESSAGE("leaflet_closure opening ratio: open "
          << ao.opening_ratio << " (raster error " << ao.raster_error / ao.disc_area << "), closed "
          << ac.opening_ratio << " (raster error " << ac.raster_error / ac.disc_area << ")");
  CHECK(std::abs(ao.opening_ratio - (1 - (t / Rv - t * t / (4 * Rv * Rv)))) <=
        ao.raster_error / ao.disc_area + 1.8e-4);
  CHECK(ac.opening_ratio + ac.raster_error / ac.disc_area <
        ao.opening_ratio - ao.raster_error / ao.disc_area);
  // One closed leaflet covers less than three.
  Leaflets one;
  one.add(c.mesh, c.result.x);
  CHECK(area_of(one, v).area > ac.area + ac.raster_error);

  // Tip: the free-edge midpoint's radial distance is what the validation case reports.
  SolidMesh m = c.mesh;
  m.node_sets["free_edge_mid"] = {c.free_edge_mid};
  const auto tip = node_set_positions(m, c.result.x, "free_edge_mid", v);
  REQUIRE(tip.size() == 1);
  CHECK(tip[0].node == c.free_edge_mid);
  CHECK(tip[0].radial ==
        doctest::Approx(std::hypot(c.result.x(0, c.free_edge_mid), c.result.x(1, c.free_edge_mid)))
            .epsilon(1e-12));
  CHECK(tip[0].axial == doctest::Approx(c.result.x(2, c.free_edge_mid)).epsilon(1e-12));
  MESSAGE("closed free-edge midpoint r/R = " << tip[0].radial / Rv);
}
