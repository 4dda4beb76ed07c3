// The time-dependent and the flow-rate drives of [forcing] through run::RunLoop, on a box
// periodic in x, y and z at 1 and 2 ranks, where a uniform force only moves the fluid as a whole
// (convection and viscosity of a uniform field vanish, its divergence is zero):
// - a sine force F0 + A sin(2 pi t / T + phi) accelerates the fluid as its time integral / rho;
//   rk4_jameson's last stage, at t^n + dt/2, makes the step the midpoint rule of that integral,
//   whose error over [0, t] is at most t dt^2 max|F''| / (24 rho);
// - a table factor s(t), piecewise linear, with steps that do not straddle its rows: the midpoint
//   rule is exact, so u = force int s dt / rho to round-off;
// - the flow-rate drive (flow/flow_rate_control.hpp) of a target Q(t) through a section across x:
//   after every step the flux is Q(t) to round-off and the force is the one that moved the bulk
//   velocity from Q(t^n) / A to Q(t^{n+1}) / A in the step, rho (Q(t^{n+1}) - Q(t^n)) / (A dt).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "analysis/section_flux.hpp"
#include "field_test_utils.hpp"
#include "run/run_loop.hpp"

using namespace valsalva;
using Vec = Eigen::Vector3d;

namespace {

constexpr double kPi = std::numbers::pi;

struct Box {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  Box() {
    mesh = mesh::generate_box(test::periodic_box("tetra", 4, 0.1));  // 1 m^3, irregular cells
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  }
};

scene::RunOptions options(double end, double dt) {
  scene::RunOptions o;
  o.projection.density = 1.3;
  o.projection.viscosity = 0.01;
  o.time.end = end;
  o.time.dt = dt;
  o.output.print = false;
  return o;
}

// Max over owned nodes of |u - expected| (collective).
double deviation(const mesh::LocalMesh& local, const flow::VectorField& u, const Vec& expected) {
  double worst = 0;
  for (int j = 0; j < local.num_owned; ++j) worst = std::max(worst, (u[j] - expected).norm());
  return local.comm.max(worst);
}

}  // namespace

TEST_CASE("a sine and a table force move a periodic box as their time integrals") {
  Box box;
  const double dt = 0.01, end = 0.5, period = 0.2, phase = 0.3;
  auto o = options(end, dt);
  o.forcing.type = flow::ForcingSpec::Type::uniform;
  o.forcing.waveform = flow::Waveform::Kind::sine;
  o.forcing.force = Vec(0.4, 0.0, -0.1);
  o.forcing.amplitude = Vec(0.0, 2.0, 1.0);
  o.forcing.period = period, o.forcing.phase = phase;
  {
    run::RunLoop loop(box.mesh, box.metrics, box.local, o);
    loop.run();
    const double w = 2 * kPi / period;
    const Vec integral = o.forcing.force * end +
                         o.forcing.amplitude * (std::cos(phase) - std::cos(w * end + phase)) / w;
    const double rho = o.projection.density;
    // Midpoint rule: |error| <= end dt^2 max|F''| / 24 / rho, max|F''| = |amplitude| w^2.
    const double bound = end * dt * dt * o.forcing.amplitude.norm() * w * w / 24 / rho;
    const double error = deviation(box.local, loop.state().velocity, integral / rho);
    CHECK(error <= bound);
    CHECK(error > 1e-3 * bound);  // the quadrature error is there: the stage times matter
    // The force field (log.csv, wall shear) follows the time.
    CHECK(((*loop.prescribed_force())[0] - o.forcing.uniform_force(end)).norm() <= 1e-14);
  }
  o.forcing.waveform = flow::Waveform::Kind::table;
  o.forcing.factor = flow::table_waveform({0.0, 0.1, 0.2}, {1.0, -2.0, 1.0});  // period 0.2
  {
    run::RunLoop loop(box.mesh, box.metrics, box.local, o);
    loop.run();
    // int_0^0.5 s dt: two periods (-0.1 each) and the first half period (-0.05).
    const Vec expected = o.forcing.force * (2 * -0.1 - 0.05) / o.projection.density;
    CHECK(deviation(box.local, loop.state().velocity, expected) <= 1e-14);
  }
}

TEST_CASE("the flow-rate drive holds the flux of a section and takes the force that does it") {
  Box box;
  const double dt = 0.01, rho = 1.3;
  auto o = options(0.3, dt);
  o.forcing.type = flow::ForcingSpec::Type::flow_rate;
  o.forcing.direction = Vec(2.0, 0.0, 0.0);  // normalised by the drive
  o.forcing.section = "cut";
  o.forcing.flow_rate.kind = flow::Waveform::Kind::sine;
  o.forcing.flow_rate.mean = 0.5, o.forcing.flow_rate.amplitude = 0.2;
  o.forcing.flow_rate.period = 0.25;
  analysis::SectionOptions cut;
  cut.name = "cut", cut.point = Vec(0.55, 0.5, 0.5), cut.normal = Vec(1, 0, 0);
  const auto section = std::make_shared<analysis::SectionFlux>(box.local, cut);
  o.section_flux = [section](const flow::EdgeField& f) { return section->flux(f); };
  run::RunLoop loop(box.mesh, box.metrics, box.local, o);
  const auto& q = o.forcing.flow_rate;
  const double area = 1.0;  // the box's section across x
  double worst_flux = 0, worst_force = 0, worst_velocity = 0, previous = 0;  // at rest: Q = 0
  run::RunHooks hooks;
  hooks.after_step = [&](const flow::FlowState& state, std::int64_t) {
    const double t = state.time;
    worst_flux = std::max(worst_flux, std::abs(section->flux(loop.face_flux()) / q(t) - 1));
    const double force = (*loop.prescribed_force())[0].x();
    const double expected = rho * (q(t) - previous) / (area * dt);
    previous = q(t);
    worst_force = std::max(worst_force, std::abs(force - expected) / (rho * 0.2 * 2 * kPi / 0.25));
    worst_velocity = std::max(worst_velocity,
                              deviation(box.local, state.velocity, Vec(q(t) / area, 0, 0)) / q(t));
  };
  loop.set_hooks(hooks);
  const auto summary = loop.run();
  CHECK(summary.steps == 30);
  CHECK(worst_flux <= 1e-13);
  CHECK(worst_velocity <= 1e-12);
  // Relative to rho |Q'|max / A; step 1 jumps from rest (Q = 0) to Q(dt), as expected too.
  CHECK(worst_force <= 1e-10);
  CHECK(loop.forcing_state().size() == 1);
}
