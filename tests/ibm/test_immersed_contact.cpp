// Contact in the immersed-boundary coupling: two slabs of one body, the upper one sunk into the
// lower one, in a periodic fluid box at rest. The contact forces join the spread forces (the
// slabs are pushed apart and the penetration falls), the net force of the two half passes stays
// small against the contact force, the contact springs lower the coupling's stable time step,
// and the markers agree with a one-rank run.
#include <doctest/doctest.h>

#include "ib_box.hpp"

using namespace valsalva;

namespace {

Eigen::Vector3d fluid_momentum(const test::IbBox& box) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < box.local.num_owned; ++i) p += box.local.volume[i] * box.state.velocity[i];
  return {box.local.comm.sum(p.x()), box.local.comm.sum(p.y()), box.local.comm.sum(p.z())};
}

}  // namespace

TEST_CASE("contact pushes two immersed slabs apart, at any rank count") {
  test::IbBoxSpec spec;
  spec.cells = 12;
  spec.contact_slabs = true;
  test::IbBox box(spec);
  const auto& body = box.ib->body(0);
  REQUIRE(body.has_contact());
  const auto c0 = body.contact_summary(box.ib->positions());
  CHECK(c0.min_gap == doctest::Approx(-spec.overlap).epsilon(1e-9));
  CHECK(c0.area == doctest::Approx(spec.side * spec.side).epsilon(1e-9));
  // The penalty pressure eps * overlap on the whole face.
  CHECK(
      c0.force ==
      doctest::Approx(c0.surfaces[0].penalty * spec.overlap * spec.side * spec.side).epsilon(1e-9));

  // The contact springs enter the bound.
  auto open_spec = spec;
  open_spec.contact = false;
  test::IbBox open(open_spec);
  const double dt_contact = box.ib->stable_time_step(), dt_open = open.ib->stable_time_step();
  MESSAGE("stable dt with contact " << dt_contact << ", without " << dt_open);
  CHECK(dt_contact < 0.9 * dt_open);

  const double dt = 0.5 * dt_contact;
  double worst_imbalance = 0;
  for (int n = 0; n < 40; ++n) {
    box.step(dt);
    const auto c = body.contact_summary(box.ib->positions());
    if (c.force > 0)
      worst_imbalance = std::max(worst_imbalance, box.ib->total_force(0).norm() / c.force);
  }
  const auto c1 = body.contact_summary(box.ib->positions());
  MESSAGE("min gap " << c0.min_gap << " -> " << c1.min_gap << ", force " << c0.force << " -> "
                     << c1.force << ", largest |net force| / contact force " << worst_imbalance
                     << ", fluid momentum " << fluid_momentum(box).transpose());
  // The slabs separate through the fluid: measured penetration 0.020 -> 0.011 in 40 steps.
  CHECK(c1.min_gap > 0.75 * c0.min_gap);
  // two_pass (the FSI default): every point's forces cancel, so the net force is round-off.
  CHECK(worst_imbalance < 1e-12);

  if (box.local.comm.size() > 1) {
    const double diff = test::marker_difference_to_serial(spec, box, 40, dt);
    MESSAGE("np " << box.local.comm.size() << " vs 1: max marker difference " << diff);
    // As in test_immersed_structure: the pressure solve's tolerance (1e-8) with a different AMG
    // hierarchy per rank count, not round-off.
    CHECK(diff < 1e-10);
  }
}

TEST_CASE("two_half_pass contact in the coupling: the net force it leaves") {
  // The two half passes act on different faces with their own gaps and areas: their forces are
  // equal and opposite on a uniform state only. Measured here as the slabs deform over 40 steps
  // of half the coupling's bound (2x2 on 3x3 faces): up to 41 % of the contact force (14 % with
  // the smaller steps of the earlier, diagonal contact bound), which the coupling spreads into
  // the fluid; hence two_pass in flow runs.
  test::IbBoxSpec spec;
  spec.cells = 12;
  spec.contact_slabs = true;
  spec.formulation = structure::ContactOptions::Formulation::two_half_pass;
  test::IbBox box(spec);
  const auto& body = box.ib->body(0);
  box.ib->current_force_density(box.state.velocity);  // forces at the start (output call)
  const double f0 = body.contact_summary(box.ib->positions()).force;
  CHECK(box.ib->total_force(0).norm() < 1e-12 * f0);  // uniform start: balanced
  box.state.velocity.assign(box.state.velocity.size(), Eigen::Vector3d::Zero());
  const double dt = 0.5 * box.ib->stable_time_step();
  double worst = 0;
  for (int n = 0; n < 40; ++n) {
    box.step(dt);
    worst = std::max(
        worst, box.ib->total_force(0).norm() / body.contact_summary(box.ib->positions()).force);
  }
  MESSAGE("two_half_pass: largest |net force| / contact force " << worst);
  CHECK(worst > 1e-3);  // the imbalance is real (documented), unlike two_pass
  CHECK(worst < 0.5);
}
