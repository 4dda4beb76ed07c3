// Lumped outlets (flow/lumped_outlets.hpp): the distal-pressure integrator against the exact
// solution for a linear flux, a resistance outlet on a channel against a fixed-pressure outlet
// (one outlet: the velocity does not see the outlet pressure, the pressure shifts by p0 + R Q),
// two RCR outlets in parallel (the projection uses the pressure the law gives at the end-of-step
// flux, to round-off) and the refusal of non-positive parameters; the lumped ventricle's affine
// law and its venous return against the RCR's own update (volume conserved).
#include <doctest/doctest.h>

#include <cmath>

#include "field_test_utils.hpp"
#include "flow/lumped_outlets.hpp"
#include "run/run_loop.hpp"

using namespace valsalva;

namespace {

struct Box {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  explicit Box(bool periodic_z) {
    mesh::BoxSpec box;
    box.cells = {12, 4, 3};
    box.length = Eigen::Vector3d(3.0, 1.0, 0.75);
    box.periodic = {false, false, periodic_z};
    mesh = mesh::generate_box(box);
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  }
  int patch(const std::string& name) const {
    for (std::size_t p = 0; p < local.patch_names.size(); ++p)
      if (local.patch_names[p] == name) return static_cast<int>(p);
    return -1;
  }
};

scene::RunOptions options(double end) {
  scene::RunOptions o;
  o.projection.density = 1.0;
  o.projection.viscosity = 0.05;
  o.projection.poisson.tolerance = 1e-12;
  o.time.end = end;
  o.time.dt = 0.01;
  o.output.print = false;
  return o;
}

flow::BoundarySpec inlet(double mean, double amplitude) {
  auto s = flow::boundary_spec("xmin", flow::BoundaryType::inlet);
  s.flow_rate.kind = flow::Waveform::Kind::sine;
  s.flow_rate.mean = mean;
  s.flow_rate.amplitude = amplitude;
  s.flow_rate.period = 0.5;
  return s;
}

flow::BoundarySpec rcr(const std::string& patch, double rp, double rd, double c) {
  auto s = flow::boundary_spec(patch, flow::BoundaryType::rcr_outlet);
  s.resistance = rp, s.distal_resistance = rd, s.capacitance = c;
  return s;
}

}  // namespace

TEST_CASE("distal pressure update: exact for a flux linear in time, any h = dt / tau") {
  const double rd = 2.0, c = 0.5, tau = rd * c, p0 = 0.3, a = 1.5, b = -0.8;
  for (double h : {1e-8, 1e-5, 9.99e-4, 1.001e-3, 0.1, 1.0, 30.0, 1e3}) {
    const double dt = h * tau;
    auto spec = rcr("o", 1.0, rd, c);
    flow::LumpedState state{a, 0, p0, 0};
    // dp/dt = -p/tau + (a + b t)/C: p = R_d (a + b t) - R_d b tau + (p0 - R_d a + R_d b tau)
    // e^{-t/tau}
    const double exact =
        rd * (a + b * dt) - rd * b * tau + (p0 - rd * a + rd * b * tau) * std::exp(-h);
    const double got = flow::distal_after(spec, state, a + b * dt, dt);
    CHECK(got == doctest::Approx(exact).epsilon(1e-13));
    const auto w = flow::distal_weights(h);
    CHECK(w.w0 + w.w1 == doctest::Approx(-std::expm1(-h)).epsilon(1e-14));
    // The law's affine form: P^{n+1} = offset + slope Q^{n+1} = p_d^{n+1} + R_p Q^{n+1}.
    const auto step = flow::outlet_step(spec, state, dt);
    CHECK(step.offset + step.slope * (a + b * dt) == doctest::Approx(got + a + b * dt));
  }
  // Series and closed form meet at h = 1e-3.
  const auto below = flow::distal_weights(1e-3 * (1 - 1e-12)), above = flow::distal_weights(1e-3);
  CHECK(below.w0 == doctest::Approx(above.w0).epsilon(1e-11));
  CHECK(below.w1 == doctest::Approx(above.w1).epsilon(1e-11));
}

TEST_CASE("elastance inlet: the affine law is E(t) (V^{n+1} - V0), the venous volume the RCR's") {
  auto lv = flow::boundary_spec("lv", flow::BoundaryType::elastance_inlet);
  lv.elastance = {false, 2e7, 5e8, 0.5, 0.2, {}};
  lv.rest_volume = 2e-7;
  const auto ao = rcr("ao", 2e7, 1e8, 1e-9);
  // Raised cosine: E_min at t = 0 and from the end of systole on, E_max at T_s / 2.
  CHECK(lv.elastance(0.0) == 2e7);
  CHECK(lv.elastance(0.1) == doctest::Approx(5e8).epsilon(1e-15));
  CHECK(lv.elastance(0.35) == 2e7);
  CHECK(lv.elastance(0.6) == doctest::Approx(lv.elastance(0.1)).epsilon(1e-15));
  const double dt = 2e-3, t_next = 0.07, q0 = -3e-6, q1 = -4e-6;
  const flow::LumpedState ventricle{q0, 300, 1.1e-6, 0}, artery{-q0, 280, 250, 0};
  const auto step = flow::outlet_step(lv, ventricle, dt, t_next);
  const double volume = flow::distal_after(lv, ventricle, q1, dt);
  CHECK(volume == doctest::Approx(1.1e-6 + 0.5 * dt * (q0 + q1)).epsilon(1e-15));
  CHECK(step.offset + step.slope * q1 ==
        doctest::Approx(lv.elastance(t_next) * (volume - 2e-7)).epsilon(1e-13));
  // Venous volume: D = d0 + d1 Q_r^{n+1} equals dt (Q_r^n + Q_r^{n+1}) / 2 - C dp_d, so V + C p_d
  // changes by dt/2 times the sum of the two fluxes (0 here: Q_r = -Q).
  const auto v = flow::venous_step(ao, artery, dt);
  const double pd = flow::distal_after(ao, artery, -q1, dt);
  const double venous = 0.5 * dt * (-q0 - q1) - 1e-9 * (pd - 250);
  CHECK(v.d0 + v.d1 * -q1 == doctest::Approx(venous).epsilon(1e-10));
  CHECK(std::abs((volume + venous + 1e-9 * pd) - (1.1e-6 + 1e-9 * 250)) <= 1e-20);
}

TEST_CASE(
    "one resistance outlet: same velocity as a pressure outlet, pressure shifted by p0 + R Q") {
  Box box(true);
  const double p0 = 40, r = 300;
  auto run = [&](flow::BoundarySpec outlet) {
    auto o = options(0.2);
    o.boundary = {inlet(0.6, 0.3), std::move(outlet),
                  flow::boundary_spec("ymin", flow::BoundaryType::wall),
                  flow::boundary_spec("ymax", flow::BoundaryType::wall)};
    auto loop = std::make_unique<run::RunLoop>(box.mesh, box.metrics, box.local, o);
    loop->run();
    return loop;
  };
  const auto fixed = run(flow::boundary_spec("xmax", flow::BoundaryType::pressure_outlet));
  auto spec = flow::boundary_spec("xmax", flow::BoundaryType::resistance_outlet);
  spec.pressure = p0, spec.resistance = r;
  const auto lumped = run(spec);
  const auto& a = fixed->state();
  const auto& b = lumped->state();
  const double q = lumped->boundary()->patch_fluxes(b.velocity)[box.patch("xmax")];
  const auto& outlet = lumped->solver().lumped_outlets()->state(0);
  CHECK(outlet.flux == doctest::Approx(q).epsilon(1e-14));
  CHECK(outlet.pressure == doctest::Approx(p0 + r * q).epsilon(1e-14));
  double du = 0, dp = 0, umax = 0;
  for (int j = 0; j < box.local.num_owned; ++j) {
    du = std::max(du, (a.velocity[j] - b.velocity[j]).norm());
    umax = std::max(umax, a.velocity[j].norm());
    dp = std::max(dp, std::abs(b.pressure[j] - a.pressure[j] - outlet.pressure));
  }
  du = box.local.comm.max(du), dp = box.local.comm.max(dp), umax = box.local.comm.max(umax);
  MESSAGE("Q " << q << " P " << outlet.pressure << ": max |du| " << du << " of " << umax
               << ", max |p - p_fixed - P| " << dp);
  // The Poisson tolerance (1e-12) over 20 steps.
  CHECK(du < 1e-9 * umax);
  CHECK(dp < 1e-8 * outlet.pressure);
}

TEST_CASE("two RCR outlets: the projection uses the law's end-of-step pressure, to round-off") {
  Box box(false);
  auto o = options(0.3);
  // ymax takes twice xmax's resistances; R C spans stiff (h = 1e3) and slow (h = 1e-4) outlets.
  o.boundary = {inlet(0.6, 0.4),
                rcr("xmax", 50, 500, 2e-5),
                rcr("ymax", 100, 1e4, 10.0),
                flow::boundary_spec("ymin", flow::BoundaryType::wall),
                flow::boundary_spec("zmin", flow::BoundaryType::slip),
                flow::boundary_spec("zmax", flow::BoundaryType::slip)};
  run::RunLoop loop(box.mesh, box.metrics, box.local, o);
  double worst = 0, scale = 0;
  run::RunHooks hooks;
  hooks.after_step = [&](const flow::FlowState&, std::int64_t) {
    const auto* lumped = loop.solver().lumped_outlets();
    worst = std::max(worst, lumped->last_mismatch());
    for (int k = 0; k < lumped->count(); ++k)
      scale = std::max(scale, std::abs(lumped->state(k).pressure));
  };
  loop.set_hooks(hooks);
  const auto summary = loop.run();
  const auto* lumped = loop.solver().lumped_outlets();
  const auto flux = loop.boundary()->patch_fluxes(loop.state().velocity);
  MESSAGE("P " << lumped->state(0).pressure << ", " << lumped->state(1).pressure << " Pa; Q "
               << flux[box.patch("xmax")] << ", " << flux[box.patch("ymax")] << "; max mismatch "
               << worst << " of " << scale);
  CHECK(worst < 1e-10 * scale);
  CHECK(summary.max_mass_imbalance < 1e-13);
  CHECK(flux[box.patch("xmax")] == doctest::Approx(lumped->state(0).flux).epsilon(1e-14));
  // Both carry some of the inflow: ymax, whose large C holds p_d near 0 over the run (impedance
  // about R_p = 100 against xmax's R_p + R_d = 550, C small), the larger share (measured 0.166
  // for the flux ratio xmax / ymax, 100 / 550 = 0.18 without the channel's own resistance).
  CHECK(flux[box.patch("ymax")] > flux[box.patch("xmax")]);
  CHECK(flux[box.patch("xmax")] > 0);
}

TEST_CASE("a resistance outlet next to a fixed pressure outlet: shared nodes keep the fixed one") {
  Box box(false);
  auto o = options(0.2);
  auto outlet = flow::boundary_spec("ymax", flow::BoundaryType::resistance_outlet);
  outlet.pressure = 5, outlet.resistance = 20;
  auto fixed = flow::boundary_spec("xmax", flow::BoundaryType::pressure_outlet);
  fixed.pressure = -3;
  o.boundary = {inlet(0.6, 0.4),
                fixed,
                outlet,
                flow::boundary_spec("ymin", flow::BoundaryType::wall),
                flow::boundary_spec("zmin", flow::BoundaryType::wall),
                flow::boundary_spec("zmax", flow::BoundaryType::wall)};
  run::RunLoop loop(box.mesh, box.metrics, box.local, o);
  double worst = 0;
  run::RunHooks hooks;
  hooks.after_step = [&](const flow::FlowState&, std::int64_t) {
    worst = std::max(worst, loop.solver().lumped_outlets()->last_mismatch());
  };
  loop.set_hooks(hooks);
  loop.run();
  const auto& s = loop.state();
  const auto& lumped = loop.solver().lumped_outlets()->state(0);
  const auto flux = loop.boundary()->patch_fluxes(s.velocity);
  // Nodes on both patches (the edge x = 3, y = 1) hold -3 Pa, the rest of ymax P = 5 + 20 Q.
  int shared = 0, own = 0, wrong = 0;
  for (int j = 0; j < box.local.num_owned; ++j) {
    const auto& x = box.local.position[j];
    if (std::abs(x.y() - 1) > 1e-12) continue;
    const bool corner = std::abs(x.x() - 3) < 1e-12;
    (corner ? shared : own) += 1;
    wrong += s.pressure[j] != (corner ? -3.0 : lumped.pressure);
  }
  MESSAGE("P " << lumped.pressure << " Q " << flux[box.patch("ymax")] << " fixed outlet Q "
               << flux[box.patch("xmax")] << ", mismatch " << worst);
  CHECK(box.local.comm.sum(static_cast<std::int64_t>(shared)) == 4 * 1);  // 4 nodes along z
  CHECK(box.local.comm.sum(static_cast<std::int64_t>(wrong)) == 0);
  CHECK(lumped.pressure == doctest::Approx(5 + 20 * flux[box.patch("ymax")]).epsilon(1e-14));
  CHECK(worst < 1e-10 * std::abs(lumped.pressure));
}

TEST_CASE("lumped outlets refuse non-positive resistance and capacitance") {
  Box box(true);
  for (int bad = 0; bad < 3; ++bad) {
    auto outlet = rcr("xmax", 1, 1, 1);
    (bad == 0   ? outlet.resistance
     : bad == 1 ? outlet.distal_resistance
                : outlet.capacitance) = bad == 2 ? 0.0 : -1.0;
    const std::vector<flow::BoundarySpec> specs = {
        inlet(1, 0), outlet, flow::boundary_spec("ymin", flow::BoundaryType::wall),
        flow::boundary_spec("ymax", flow::BoundaryType::wall)};
    CHECK_THROWS_WITH_AS(flow::BoundaryConditions(box.local, specs, 0.1),
                         doctest::Contains("must be a positive finite number"),
                         std::invalid_argument);
  }
}
