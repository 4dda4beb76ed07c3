// Per-leaflet fibre axes for the HGO law: each element's e1 is its leaflet's circumferential
// direction and e2 its radial one, so the three leaflets (120 degrees apart) respond alike to
// the same deformation in their own frames. Checked through structure::SolidForces: under an
// axisymmetric deformation the nodal forces of leaflet 2 are those of leaflet 1 rotated by
// 120 degrees; with one global fibre direction (x) they are not.
#include <doctest/doctest.h>

#include <cmath>

#include "structure/hex_element.hpp"
#include "structure/solid_forces.hpp"
#include "valve/leaflet_fibres.hpp"
#include "valve/leaflet_mesh.hpp"

using namespace valsalva;
using structure::Vec3;

namespace {

structure::HgoParameters hgo() {
  structure::HgoParameters p;
  p.mu = 2.4e6;
  p.K = 1.6e6;
  p.k1 = 5e6;
  p.k2 = 10;
  p.kappa = 0.1;
  p.gamma = 0.3;
  return p;
}

// Axisymmetric deformation: r -> r + 1 mm (circumferential stretch ~1.08, fibres in tension),
// z -> 1.05 z.
Eigen::Matrix3Xd deform(const Eigen::Matrix3Xd& X) {
  Eigen::Matrix3Xd x = X;
  for (int n = 0; n < X.cols(); ++n) {
    const double r = std::hypot(X(0, n), X(1, n)), s = (r + 1e-3) / r;
    x(0, n) = s * X(0, n);
    x(1, n) = s * X(1, n);
    x(2, n) = 1.05 * X(2, n);
  }
  return x;
}

// Largest |f_2 - Q f_1| over corresponding nodes of leaflets 1 and 2, relative to max |f|.
double rotation_mismatch(const structure::SolidMesh& m, const Eigen::Matrix3Xd& f) {
  const auto& l1 = m.node_set("leaflet1");
  const auto& l2 = m.node_set("leaflet2");
  REQUIRE(l1.size() == l2.size());
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(2 * M_PI / 3, Vec3::UnitZ()).toRotationMatrix();  // leaflet 1 -> 2
  double worst = 0;
  for (std::size_t k = 0; k < l1.size(); ++k) {
    REQUIRE((m.X.col(l2[k]) - Q * m.X.col(l1[k])).norm() < 1e-12);  // same local node
    worst = std::max(worst, (f.col(l2[k]) - Q * f.col(l1[k])).norm());
  }
  return worst / f.colwise().norm().maxCoeff();
}

}  // namespace

// The largest angle between each element's circumferential axis and e_theta at its centre node,
// checking on the way that the radial axis is e_z (in the cylinder surface, towards the free edge).
double worst_circumferential_angle(double side_element_ratio) {
  valve::ValveGeometry g;
  g.mesh_size = 2e-3;
  g.leaflet_side_element_ratio = side_element_ratio;
  const structure::SolidMesh m = valve::valve_leaflets(g);
  const auto axes = valve::leaflet_fibre_axes(m);
  REQUIRE(axes.size() == std::size_t(m.num_elements()));
  double worst = 0;
  for (int e = 0; e < m.num_elements(); ++e) {
    Vec3 c = Vec3::Zero();  // the centre node (reference point 0), where the axes are taken
    for (int a = 0; a < 27; ++a)
      if (structure::hex_reference_node(structure::HexOrder::q2, a).norm() == 0)
        c = m.X.col(m.element_nodes(e)[a]);
    const double th = std::atan2(c.y(), c.x());
    const Vec3 e_theta(-std::sin(th), std::cos(th), 0), e_r(std::cos(th), std::sin(th), 0);
    CAPTURE(e);
    CHECK(axes[e].circumferential.dot(e_theta) > 0);  // counter-clockwise arc
    worst = std::max(worst, std::acos(std::min(1.0, axes[e].circumferential.dot(e_theta))));
    CHECK(std::abs(axes[e].radial.dot(e_r)) < 1e-12);
    CHECK(axes[e].radial.z() > 1 - 1e-12);  // a cylinder: radial = axial
  }
  return worst;
}

TEST_CASE("leaflet fibre axes: circumferential and radial per element") {
  // Uniform arc: the quadratic through three equally spaced nodes of a circle is tangent to it
  // at the middle one, so the axes are exact to round-off.
  CHECK(worst_circumferential_angle(1.0) < 1e-6);
  // The default graded arc (narrower elements at the posts): the middle node is off the
  // element's angular middle, and the quadratic's tangent there turns by about half the
  // difference of the two node spacings over R, below a degree at 2 mm.
  const double graded =
      worst_circumferential_angle(valve::ValveGeometry{}.leaflet_side_element_ratio);
  MESSAGE("graded arc: largest angle to e_theta " << graded * 180 / M_PI << " deg");
  CHECK(graded < M_PI / 180);
}

TEST_CASE("per-element HGO: the three leaflets respond alike in their own frames") {
  valve::ValveGeometry g;
  g.mesh_size = 3e-3;
  const structure::SolidMesh m = valve::valve_leaflets(g);
  const Eigen::Matrix3Xd x = deform(m.X);
  Eigen::Matrix3Xd f(3, m.num_nodes());

  const auto local = valve::hgo_per_element(hgo(), valve::leaflet_fibre_axes(m));
  const structure::SolidForces per_element(m, valve::element_pointers(local));
  CHECK(per_element.internal_forces(x, f) > 0);
  const double local_mismatch = rotation_mismatch(m, f);
  CHECK(local_mismatch < 1e-10);  // round-off

  const auto global = structure::make_hgo(hgo());  // fibres from global x and y
  const structure::SolidForces one_material(m, *global);
  one_material.internal_forces(x, f);
  const double global_mismatch = rotation_mismatch(m, f);
  MESSAGE("force mismatch between leaflets 1 and 2: per-element axes "
          << local_mismatch << ", global axes " << global_mismatch);
  CHECK(global_mismatch > 1e-2);

  // The per-element constructor with one material everywhere gives the single-material forces
  // (the neo-Hookean pack kernel against the generic per-point call).
  const auto nh = structure::make_neo_hookean(2.4e6, 1.6e6);
  const structure::SolidForces a(m, *nh);
  const structure::SolidForces b(
      m, std::vector<const structure::Material*>(m.num_elements(), nh.get()));
  Eigen::Matrix3Xd fa(3, m.num_nodes()), fb(3, m.num_nodes());
  a.internal_forces(x, fa);
  b.internal_forces(x, fb);
  CHECK((fa - fb).cwiseAbs().maxCoeff() <= 1e-10 * fa.cwiseAbs().maxCoeff());
  CHECK_THROWS_AS(structure::SolidForces(m, std::vector<const structure::Material*>(3, nh.get())),
                  std::invalid_argument);
}
