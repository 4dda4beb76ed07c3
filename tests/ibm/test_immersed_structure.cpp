// The ITBM coupling (ibm::ImmersedStructure) on a stretched neo-Hookean block relaxing in a
// periodic box of fluid at rest:
// - lumped nodal volumes add up to the solid volume; tether forces and their reaction;
// - spreading conserves momentum: internal forces sum to zero, so the fluid momentum
//   sum_j V_j u_j stays zero to round-off while the block relaxes (elastic energy decreases);
// - the result does not depend on the rank count (against the same run on one rank, to the
//   Poisson tolerance);
// - a time step above the bound of ib_stability.hpp is refused with an explanation;
// - per-stage coupling moves the markers with the time scheme's stage weights: in uniform
//   stage velocities u_k = (k + 1) U (interpolated exactly: partition of unity) a step moves
//   them by dt sum_k b_k (k + 1) U = 4 dt U (rk4_jameson) or 2.5 dt U (rk4_classic); classic
//   steps of the relaxing block agree across rank counts.
#include <doctest/doctest.h>

#include <cmath>

#include "ib_box.hpp"

using namespace valsalva;
using Vec = Eigen::Vector3d;

namespace {

double elastic_energy(const test::IbBox& box) {
  // Strain energy by Gauss quadrature is not exposed; the work measure here is the force norm,
  // which vanishes at the stress-free state.
  return box.ib->forces().norm();
}

Vec fluid_momentum(const test::IbBox& box) {
  Vec p = Vec::Zero();
  for (int i = 0; i < box.local.num_owned; ++i) p += box.local.volume[i] * box.state.velocity[i];
  return Vec(box.local.comm.sum(p.x()), box.local.comm.sum(p.y()), box.local.comm.sum(p.z()));
}

}  // namespace

TEST_CASE("lumped nodal volumes and tether forces") {
  test::IbBoxSpec spec;
  test::IbBox box(spec);
  const auto& body = box.ib->body(0);
  CHECK(body.nodal_volume().sum() == doctest::Approx(std::pow(spec.side, 3)).epsilon(1e-13));
  CHECK(body.nodal_volume().minCoeff() > 0);
  // Marker spacing: Q2 nodes half an element apart.
  CHECK(body.max_marker_spacing(box.solid.X) ==
        doctest::Approx(spec.side / spec.elements / 2).epsilon(1e-12));

  // A clamped face displaced rigidly by d: the tether pulls back with -k d per node, and the
  // internal forces of a rigid translation vanish, so the total is the tether reaction.
  structure::SolidMesh solid = box.solid;
  auto material = structure::make_neo_hookean(1.0, 10.0);
  ibm::ImmersedOptions options;
  options.box = ibm::PeriodicBox{{0, 0, 0}, {1, 1, 1}, {true, true, true}};
  ibm::ImmersedStructure ib(box.local, options);
  CHECK_THROWS_WITH_AS(ib.add_body(solid, *material, {"leaf", {"u0"}, 0.0}),
                       doctest::Contains("positive tether stiffness"), std::invalid_argument);
  ibm::ImmersedStructure tethered(box.local, options);
  const double k = 250.0;
  tethered.add_body(solid, *material, {"leaf", {"u0"}, k});
  const Vec d(0.01, -0.02, 0.005);
  Eigen::Matrix3Xd x = solid.X.colwise() + d;
  tethered.set_positions(x);
  flow::VectorField density(box.local.num_local());
  flow::VectorField u(box.local.num_local(), Vec::Zero());
  tethered.stage_force(0, 0.0, u, density);
  const double clamped = static_cast<double>(solid.node_set("u0").size());
  CHECK((tethered.tether_force(0) + k * clamped * d).norm() < 1e-12 * k * clamped * d.norm());
  CHECK((tethered.total_force(0) - tethered.tether_force(0)).norm() < 1e-10 * k * d.norm());
  // Spreading conserves the total force: sum_j V_j f_j = sum_a F_a.
  Vec spread = Vec::Zero();
  for (int i = 0; i < box.local.num_owned; ++i) spread += box.local.volume[i] * density[i];
  spread = Vec(box.local.comm.sum(spread.x()), box.local.comm.sum(spread.y()),
               box.local.comm.sum(spread.z()));
  CHECK((spread - tethered.total_force(0)).norm() < 1e-11 * tethered.total_force(0).norm());
}

TEST_CASE("a stretched block relaxes in fluid at rest, conserving momentum, at any rank count") {
  for (auto mode : {ibm::CouplingMode::per_stage, ibm::CouplingMode::per_step}) {
    CAPTURE(static_cast<int>(mode));
    test::IbBoxSpec spec;
    spec.cells = 12;
    spec.mode = mode;
    spec.poisson_tolerance = 1e-13;
    test::IbBox box(spec);
    const double dt_max = box.ib->stable_time_step();
    const double dt = 0.5 * dt_max;
    box.step(dt);
    const double f0 = elastic_energy(box);
    double worst_momentum = 0, scale = 0;
    for (int n = 1; n < 40; ++n) {
      box.step(dt);
      worst_momentum = std::max(worst_momentum, fluid_momentum(box).norm());
      double s = 0;
      for (int i = 0; i < box.local.num_owned; ++i)
        s += box.local.volume[i] * box.state.velocity[i].norm();
      scale = std::max(scale, box.local.comm.sum(s));
    }
    const double f1 = elastic_energy(box);
    MESSAGE("mode " << static_cast<int>(mode) << ": dt_max " << dt_max << ", |F| " << f0 << " -> "
                    << f1 << ", max |momentum| " << worst_momentum << " (scale " << scale << ")");
    CHECK(f1 < 0.8 * f0);
    CHECK(worst_momentum < 1e-12 * scale);

    // The same on one rank: markers agree to round-off.
    if (box.local.comm.size() > 1) {
      const double diff = test::marker_difference_to_serial(spec, box, 40, dt);
      MESSAGE("np " << box.local.comm.size() << " vs 1: max marker difference " << diff);
      // Each rank count solves the pressure Poisson equation to a relative residual of 1e-8 with
      // a different AMG hierarchy: the difference is that solver tolerance times the small
      // pressure increments, not round-off.
      CHECK(diff < 1e-10);
    }

    // Refusal above the bound, with the reason.
    CHECK_THROWS_WITH_AS(box.ib->check_time_step(1.5 * dt_max),
                         doctest::Contains("exceeds the stability limit"), std::runtime_error);
    CHECK_NOTHROW(box.ib->check_time_step(0.9 * dt_max));
  }
}

TEST_CASE("per-stage coupling moves the markers with the time scheme's weights") {
  const Vec u(0.3, -0.1, 0.05);
  const double dt = 1e-3;
  for (auto scheme : {flow::TimeScheme::rk4_jameson, flow::TimeScheme::rk4_classic}) {
    CAPTURE(flow::time_scheme_name(scheme));
    test::IbBoxSpec spec;
    spec.time_scheme = scheme;
    test::IbBox box(spec);
    const auto rk = flow::tableau(scheme);
    const Eigen::Matrix3Xd x0 = box.ib->positions();
    flow::VectorField force;
    for (int k = 0; k < 4; ++k) {
      const flow::VectorField stage(box.local.num_local(), (k + 1) * u);
      box.ib->stage_force(k, rk.c[k] * dt, stage, force);
      // The markers' velocity is interpolated from the uniform stage field.
      CHECK((box.ib->velocities().col(0) - (k + 1) * u).norm() < 1e-12 * u.norm());
    }
    box.state.time = dt;
    box.ib->finish_step(box.state);
    double moved = 0;
    for (int k = 0; k < 4; ++k) moved += rk.b[k] * (k + 1);
    CHECK(moved == doctest::Approx(scheme == flow::TimeScheme::rk4_classic ? 2.5 : 4.0));
    const Eigen::Matrix3Xd expected = x0.colwise() + dt * moved * u;
    CHECK((box.ib->positions() - expected).cwiseAbs().maxCoeff() < 1e-14);
  }
}

TEST_CASE("a classic-RK4 step of the relaxing block agrees across rank counts") {
  test::IbBoxSpec spec;
  spec.time_scheme = flow::TimeScheme::rk4_classic;
  spec.poisson_tolerance = 1e-12;
  test::IbBox box(spec);
  if (box.local.comm.size() == 1) return;  // the np 2 run compares with one rank
  const double dt = 0.5 * box.ib->stable_time_step();
  for (int n = 0; n < 3; ++n) box.step(dt);
  const double diff = test::marker_difference_to_serial(spec, box, 3, dt);
  MESSAGE("classic: marker difference to one rank " << diff);
  CHECK(diff < 1e-10);
}
