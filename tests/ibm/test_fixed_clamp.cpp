// Clamped nodes held exactly (ibm::Clamp::fixed): no markers of the coupling, fixed in place,
// their elastic force carried by the support, not spread into the fluid.
#include <doctest/doctest.h>

#include "ib_box.hpp"

using namespace valsalva;

namespace {

Eigen::Vector3d fluid_momentum(const test::IbBox& box) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int n = 0; n < box.local.num_owned; ++n) p += box.local.volume[n] * box.state.velocity[n];
  return Eigen::Vector3d(box.local.comm.sum(p.x()), box.local.comm.sum(p.y()),
                         box.local.comm.sum(p.z()));
}

}  // namespace

TEST_CASE("fixed clamped nodes stay put, are no markers, and the support takes their force") {
  test::IbBoxSpec spec;
  spec.clamped_sets = {"u0"};  // the block's face x = lo
  spec.poisson_tolerance = 1e-13;
  test::IbBox box(spec);
  const auto& body = box.ib->body(0);
  const int fixed = static_cast<int>(body.fixed_nodes().size());
  REQUIRE(fixed == 49);  // the 7 x 7 nodes of a face of 3 x 3 Q2 elements
  CHECK(box.ib->num_coupled_markers() == box.ib->num_markers() - fixed);

  const Eigen::Matrix3Xd x0 = box.ib->positions();
  const double dt = 0.5 * box.ib->stable_time_step();
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  for (int n = 0; n < 20; ++n) {
    box.step(dt);
    impulse += dt * box.ib->total_force(0);  // force of the last stage, as an estimate only
  }
  double moved = 0;
  for (int a : body.fixed_nodes())
    moved = std::max(moved, (box.ib->positions().col(a) - x0.col(a)).norm());
  CHECK(moved == 0.0);
  // The stretched block relaxes: its free markers move.
  CHECK((box.ib->positions() - x0).cwiseAbs().maxCoeff() > 1e-4);
  // The force on the fluid is what the support holds (internal forces sum to zero).
  const Eigen::Vector3d f = box.ib->total_force(0), support = box.ib->tether_force(0);
  CHECK((f - support).norm() <= 1e-10 * (f.norm() + 1e-300));
  CHECK(f.norm() > 0);  // the fixed face pulls: a net force reaches the fluid
  // The fluid takes momentum only from the coupled markers' forces: it gains some (a free
  // block would leave it at round-off, tests/ibm/test_immersed_structure).
  CHECK(fluid_momentum(box).norm() > 1e-3 * impulse.norm());
}

TEST_CASE("fixed nodes add no stiffness to the coupling's time-step bound, a tether does") {
  test::IbBoxSpec spec;
  spec.clamped_sets = {"u0"};
  test::IbBox fixed(spec);
  spec.clamp = ibm::Clamp::tether;
  spec.tether_stiffness = 1e3 * spec.shear_modulus * spec.side;  // a stiff hold
  test::IbBox tethered(spec);
  const double dt_fixed = fixed.ib->stable_time_step(), dt_tether = tethered.ib->stable_time_step();
  MESSAGE("stable dt fixed " << dt_fixed << ", tethered " << dt_tether);
  // The tether's springs dominate the tethered bound (it scales as 1 / sqrt(k_t)).
  CHECK(dt_fixed > 5 * dt_tether);
}
