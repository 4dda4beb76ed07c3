// Leaflet haemodynamic indices (structure/orifice_area.hpp, structure/leaflet_indices.hpp) on
// geometries with known answers. Tolerances: `raster_error` is the library's estimate of the
// polar-grid error (half the area of the cells along the projected outline, about outline length
// x cell size), so |area - exact| <= raster_error tests that estimate as well as the area; flat
// plates with straight edges are represented exactly by the projected triangles, so nothing else
// enters; curved (Q2) edges add the inscribed-polygon deficit stated where it occurs. The
// leaflet_closure geometry (a Newton solve of about a minute) is in test_valve_indices_closure.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "leaflet_set.hpp"
#include "structure/leaflet_indices.hpp"
#include "structure/mesh_generators.hpp"
#include "structure/orifice_area.hpp"

using namespace valsalva::structure;
using valsalva::structure::testing::area_of;
using valsalva::structure::testing::Leaflets;

namespace {

const double R = 12.5e-3;

using Vec2 = Eigen::Vector2d;

// One Q2 hexahedron: the flat quadrilateral c0 c1 c2 c3 (anticlockwise seen from +z) at height z,
// thickness t, mapped bilinearly (straight edges, so its projection is the quadrilateral).
SolidMesh quad_plate(const std::array<Vec2, 4>& c, double z, double t) {
  return structured_block(HexOrder::q2, {1, 1, 1}, [&](const Vec3& s) {
    const Vec2 p = (1 - s[0]) * (1 - s[1]) * c[0] + s[0] * (1 - s[1]) * c[1] + s[0] * s[1] * c[2] +
                   (1 - s[0]) * s[1] * c[3];
    return Vec3(p.x(), p.y(), z + s[2] * t);
  });
}

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Vec2 polar(double r, double deg) {
  return {r * std::cos(deg * M_PI / 180), r * std::sin(deg * M_PI / 180)};
}

// A plate covering the disc sector [from, from + span] deg (span <= 120): origin, two points on
// the sector's rays and one on its bisector, all at 3 R, so its far edges stay outside the disc.
SolidMesh sector_plate(double from, double span, double z) {
  return quad_plate(
      {Vec2::Zero(), polar(3 * R, from), polar(3 * R, from + span / 2), polar(3 * R, from + span)},
      z, 1e-5);
}

// Three plates of 100 deg with 20 deg gaps, rotated off the grid's sector lines by 7.3 deg.
Leaflets three_plates() {
  Leaflets l;
  for (int k = 0; k < 3; ++k) l.add(sector_plate(7.3 + 120 * k, 100, 1e-3 * k));
  return l;
}

ValveFrame z_valve() {
  ValveFrame v;
  v.annulus_radius = R;
  return v;
}

}  // namespace

TEST_CASE("orifice area: an empty valve opening is the whole disc") {
  Leaflets l;
  l.add(sector_plate(0, 100, 0));
  l.x[0].row(2).array() += 1.0;     // far along the axis: still projects
  l.x[0].row(0).array() += 10 * R;  // moved off the disc sideways: covers nothing
  const OrificeArea a = area_of(l, z_valve());
  CHECK(a.area == doctest::Approx(M_PI * R * R).epsilon(1e-12));  // exact cell areas
  CHECK(a.opening_ratio == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(a.raster_error == 0.0);
}

TEST_CASE("orifice area: three flat plates leave their three 20-degree gaps open") {
  const double exact = 3 * (20.0 / 360) * M_PI * R * R;
  double previous_error = INFINITY;
  for (int rings : {64, 128, 512}) {
    CAPTURE(rings);
    OrificeOptions o;
    o.rings = rings;
    const OrificeArea a = area_of(three_plates(), z_valve(), o);
    MESSAGE("three plates, rings "
            << rings << ": |area - exact| / disc = " << std::abs(a.area - exact) / a.disc_area
            << ", raster_error / disc = " << a.raster_error / a.disc_area);
    CHECK(std::abs(a.area - exact) <= a.raster_error);
    // Outline: 6 rays of length R; estimate ~ 6 R x cell size, first order in 1/rings.
    CHECK(a.raster_error <= 6 * R * (R / rings) * 2);
    CHECK(a.raster_error < previous_error);
    previous_error = a.raster_error;
    CHECK(a.opening_ratio == doctest::Approx(a.area / (M_PI * R * R)));
  }
  // Overlapping leaflets count once: a fourth plate inside the first one's sector changes nothing
  // beyond the raster error of the outline it adds inside covered cells (none: same cells).
  Leaflets four = three_plates();
  four.add(sector_plate(20, 60, 5e-3));
  const OrificeArea a3 = area_of(three_plates(), z_valve()), a4 = area_of(four, z_valve());
  CHECK(a4.area == a3.area);
}

TEST_CASE("orifice area: the uncovered cells listed are the gaps, and sum to the area") {
  OrificeOptions o;
  o.rings = 128;
  o.list_uncovered = true;
  const OrificeArea a = area_of(three_plates(), z_valve(), o);
  REQUIRE(!a.uncovered.empty());
  double sum = 0;
  int outside_gaps = 0;
  for (const UncoveredCell& c : a.uncovered) {
    sum += c.area;
    // The gaps are the sectors [107.3, 127.3] + 120 k deg; a cell centre more than one cell
    // (R / rings radially, 2 pi r / sectors around) away from them would be misclassified.
    const double deg = std::atan2(c.centre.y(), c.centre.x()) * 180 / M_PI;
    const double into_gap = std::remainder(deg - 117.3, 120.0);  // 0 at a gap's centre
    const double r = c.centre.norm(),
                 slack_deg = 180 / M_PI * (R / o.rings) / r + 360.0 / a.sectors;
    if (std::abs(into_gap) > 10 + slack_deg) ++outside_gaps;
    CHECK(r <= R);
  }
  CHECK(outside_gaps == 0);
  CHECK(std::abs(sum - a.area) <= 1e-12 * a.disc_area);
  OrificeOptions quiet = o;
  quiet.list_uncovered = false;
  CHECK(area_of(three_plates(), z_valve(), quiet).uncovered.empty());
}

TEST_CASE("orifice area: a disc with a concentric hole of radius r leaves pi r^2") {
  // Annulus r <= rho <= 1.5 R of 64 Q2 elements around, faces cut 8 x 8: the hole is a polygon of
  // 512 chords on the Q2 arc; chord deficit (2 pi / 512)^2 / 6 = 2.5e-5 and Q2 arc error
  // (phi/2)^3 / (9 sqrt 3) = 7.5e-6 of r (phi = 2 pi / 64), i.e. 1.5e-5 in area: under 1e-4 pi r^2.
  const double r = 0.4037 * R;
  Leaflets l;
  l.add(structured_block(HexOrder::q2, {1, 64, 1}, [&](const Vec3& s) {
    const double rho = r + s[0] * (1.5 * R - r), th = 2 * M_PI * s[1];
    return Vec3(rho * std::cos(th), rho * std::sin(th), 1e-5 * s[2]);
  }));
  OrificeOptions o;
  o.face_subdivision = 8;
  const OrificeArea a = area_of(l, z_valve(), o);
  CHECK(std::abs(a.area - M_PI * r * r) <= a.raster_error + 1e-4 * M_PI * r * r);
  CHECK(a.raster_error <= 2 * M_PI * r * (R / o.rings) * 1.5);  // about one ring of cells
}

TEST_CASE("orifice area: a plate tilted by theta projects cos(theta) smaller") {
  // Square plate of side s, thickness t, centred on the axis, tilted about x: its projection is
  // s (s cos theta + t sin theta) (the tilted side faces add the t sin theta strip).
  const double s = 0.8 * R, t = 0.01 * s;
  auto covered = [&](double theta) {
    SolidMesh m = quad_plate(
        {Vec2(-s / 2, -s / 2), Vec2(s / 2, -s / 2), Vec2(s / 2, s / 2), Vec2(-s / 2, s / 2)},
        -t / 2, t);
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(theta, Vec3::UnitX()).toRotationMatrix();
    m.X = rot * m.X;
    Leaflets l;
    l.add(std::move(m));
    const OrificeArea a = area_of(l, z_valve());
    const double exact = s * (s * std::cos(theta) + t * std::sin(theta));
    CHECK(std::abs((M_PI * R * R - a.area) - exact) <= a.raster_error);
    return std::pair{M_PI * R * R - a.area, a.raster_error};
  };
  const auto [flat, e0] = covered(0);
  for (double deg : {30.0, 50.0, 75.0}) {
    CAPTURE(deg);
    const double th = deg * M_PI / 180;
    const auto [tilted, e] = covered(th);
    CHECK(std::abs(tilted / flat - (std::cos(th) + t / s * std::sin(th))) <=
          (e + e0 * std::cos(th)) / flat);
  }
}

TEST_CASE("orifice area: no bias for an outline in general position to the grid") {
  // A cell is classified by its centre, so along an outline that crosses the polar grid at
  // generic angles the misclassified parts of cells on either side cancel: the error grows like
  // the square root of the number of outline cells, not like their number, and stays a small
  // fraction of raster_error (which is the no-cancellation bound): measured 0.004 .. 0.019 here.
  // A biased classification shifts the whole outline: sampling cells 0.2 of a cell off-centre
  // radially gives 0.07, which the 0.04 bound below rejects.
  // Irregular quadrilateral, straight edges: exact area by the shoelace formula.
  const std::array<Vec2, 4> c = {polar(0.3 * R, 10), polar(0.9 * R, 40), polar(0.8 * R, 80),
                                 polar(0.2 * R, 70)};
  double exact = 0;
  for (int k = 0; k < 4; ++k) exact += 0.5 * cross2(c[k], c[(k + 1) % 4]);
  Leaflets l;
  l.add(quad_plate(c, 0, 1e-5));
  for (int rings : {128, 256, 512, 1024}) {
    CAPTURE(rings);
    OrificeOptions o;
    o.rings = rings;
    const OrificeArea a = area_of(l, z_valve(), o);
    const double err = std::abs((a.disc_area - a.area) - exact);
    MESSAGE("irregular quad, rings " << rings
                                     << ": |error| / raster_error = " << err / a.raster_error);
    CHECK(err <= 0.04 * a.raster_error);
  }
}

TEST_CASE("orifice area: invariant under rigid motion of leaflets and valve together") {
  Leaflets l = three_plates();
  l.add(quad_plate({polar(0.3 * R, 10), polar(0.9 * R, 40), polar(0.8 * R, 80), polar(0.2 * R, 70)},
                   2e-3, 1e-4));
  const OrificeArea a = area_of(l, z_valve());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::Matrix3d Q =
        Eigen::AngleAxisd(3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    const Vec3 c(u(rng), u(rng), u(rng));
    Leaflets moved = l;
    for (auto& x : moved.x) x = (Q * x).colwise() + c;
    ValveFrame v = z_valve();
    v.point = c;
    v.axis = 3.7 * (Q * Vec3::UnitZ());  // any length
    const OrificeArea b = area_of(moved, v);
    // The grid's orientation in the plane differs, so the two agree within both raster errors.
    CHECK(std::abs(a.area - b.area) <= a.raster_error + b.raster_error);
    // Moving the valve alone along its own axis changes nothing at all.
    v.point += 0.01 * v.axis;
    CHECK(area_of(moved, v).area == b.area);
  }
}

TEST_CASE("node set positions: radial and axial distances in a moved frame") {
  Bar b;
  b.n_length = 2;
  const SolidMesh m = straight_bar(HexOrder::q2, b);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 c(0.1, -0.2, 0.3);
  const Eigen::Matrix3Xd x = (Q * m.X).colwise() + c;
  ValveFrame v;
  v.point = c + Q * Vec3(0, 0.05, 0.05);  // the bar's centre line y = z = 0.05 is the axis
  v.axis = Q * Vec3(-2, 0, 0);
  v.annulus_radius = 1;
  for (const auto& p : node_set_positions(m, x, "tip", v)) {
    CHECK(p.position.isApprox(x.col(p.node)));
    CHECK(p.radial == doctest::Approx(std::hypot(m.X(1, p.node) - 0.05, m.X(2, p.node) - 0.05)));
    CHECK(p.axial == doctest::Approx(-1.0));  // tip at x = 1, axis pointing to -x
  }
}

TEST_CASE("von Mises summary: maximum and percentile") {
  NodalStress s;
  s.von_mises.resize(100);
  std::vector<int> order(100);
  for (int i = 0; i < 100; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  for (int i = 0; i < 100; ++i) s.von_mises[order[i]] = i + 1;  // values 1 .. 100
  const StressSummary a = von_mises_summary(s, 95);
  CHECK(a.max == 100);
  CHECK(a.max_node == order[99]);
  CHECK(a.at_percentile == doctest::Approx(95.05));  // position 99 * 0.95 = 94.05 (numpy value)
  CHECK(von_mises_summary(s, 0).at_percentile == 1);
  CHECK(von_mises_summary(s, 100).at_percentile == 100);
  CHECK(von_mises_summary(s, 50).at_percentile == doctest::Approx(50.5));

  // Homogeneous deformation of a bar: every node carries von_mises(sigma(F)).
  Bar b;
  b.n_length = 3;
  const SolidMesh m = straight_bar(HexOrder::q2, b);
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  const SolidForces forces(m, *mat);
  Mat3 F;
  F << 1.1, 0.05, 0, 0, 0.95, 0.02, 0, 0, 1.0;
  const Mat3 sigma = mat->pk1(F) * F.transpose() / F.determinant();
  const StressSummary h = von_mises_summary(forces, F * m.X, 90);
  CHECK(h.samples == 27 * m.num_elements());  // Gauss points of the 3x3x3 rule
  CHECK(h.max_element >= 0);
  CHECK(h.max_element < m.num_elements());
  CHECK(h.max == doctest::Approx(von_mises(sigma)).epsilon(1e-10));
  CHECK(h.at_percentile == doctest::Approx(von_mises(sigma)).epsilon(1e-10));

  // The Gauss points move with the body: under x = F X each sits at F times its reference place.
  const GaussPointStress ref = gauss_point_stress(forces, m.X),
                         moved = gauss_point_stress(forces, F * m.X);
  CHECK((moved.position - F * ref.position).cwiseAbs().maxCoeff() < 1e-14);
  // The 3x3x3 points are symmetric about the element centre, which an affine element maps to the
  // mean of its 8 corners.
  const Vec3 centre = ref.position.leftCols(27).rowwise().mean();
  Vec3 corners = Vec3::Zero();
  for (int c = 0; c < 8; ++c) corners += m.X.col(m.element_nodes(0)[c]) / 8;
  CHECK((centre - corners).norm() < 1e-14);
}

TEST_CASE("valve indices: bad input is refused with a clear message") {
  const Leaflets l = three_plates();
  const auto view = l.view();
  ValveFrame v = z_valve();
  v.axis = Vec3::Zero();
  CHECK_THROWS_WITH_AS(geometric_orifice_area(view, v), doctest::Contains("axis direction"),
                       std::invalid_argument);
  v = z_valve();
  for (double bad : {0.0, -1.0, double(NAN)}) {
    v.annulus_radius = bad;
    CHECK_THROWS_WITH_AS(geometric_orifice_area(view, v), doctest::Contains("annulus radius"),
                         std::invalid_argument);
  }
  v = z_valve();
  CHECK_THROWS_WITH_AS(geometric_orifice_area({}, v), doctest::Contains("no leaflets"),
                       std::invalid_argument);
  OrificeOptions o;
  o.rings = 0;
  CHECK_THROWS_WITH_AS(geometric_orifice_area(view, v, o), doctest::Contains("rings = 0"),
                       std::invalid_argument);
  const Eigen::Matrix3Xd short_x = l.x[0].leftCols(3);
  const LeafletPositions bad_leaflet[] = {{&l.meshes[0], &short_x}};
  CHECK_THROWS_WITH_AS(geometric_orifice_area(bad_leaflet, v),
                       doctest::Contains("3 positions for 27 nodes"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(node_set_positions(l.meshes[0], l.x[0], "free_edge_mid", v),
                       doctest::Contains("no node set 'free_edge_mid'"), std::invalid_argument);
  NodalStress s;
  CHECK_THROWS_WITH_AS(von_mises_summary(s, 50), doctest::Contains("no nodes"),
                       std::invalid_argument);
  s.von_mises = Eigen::VectorXd::Ones(3);
  CHECK_THROWS_WITH_AS(von_mises_summary(s, 101), doctest::Contains("percentile 101"),
                       std::invalid_argument);
}
