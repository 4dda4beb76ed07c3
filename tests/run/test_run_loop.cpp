// The flow run loop: a small Taylor-Green run (error against the exact solution, np = 1 and 2
// agree with a serial run to 1e-10), the refused time step beyond the RK4 stability limit, the
// blow-up diagnosis with the last good state written, no Taylor-Green error for a non-Newtonian
// fluid, the boundary-condition requirement, the
// scene reader of the flow keys (time.scheme, time.project_stages among them), and the 3D
// Taylor-Green initial state (its pressure solves lap p = -rho du_i/dx_j du_j/dx_i, checked by
// finite differences of the closed form; its first pressure increment is small).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flow/body_forcing.hpp"
#include "run/run_loop.hpp"
#include "scene/scene.hpp"
#include "scene/scene_keys_flow.hpp"
#include "tests/flow/field_test_utils.hpp"

using namespace valsalva;

namespace {

// A Taylor-Green set-up in units U0 = L = 1, rho = 1, Re = 100 on n x n x 3 hexahedra.
struct Setup {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  Setup(int n, MPI_Comm comm, bool periodic_z = true) {
    mesh::BoxSpec box;
    const double two_pi = 2 * std::numbers::pi;
    box.cells = {n, n, 3};
    box.length = Eigen::Vector3d(two_pi, two_pi, 3 * two_pi / n);
    box.periodic = {true, true, periodic_z};
    mesh = mesh::generate_box(box);
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, comm);
  }
};

scene::RunOptions tgv_options(double end) {
  scene::RunOptions o;
  o.projection.density = 1.0;
  o.projection.viscosity = 0.01;
  o.projection.poisson.tolerance = 1e-13;  // np agreement to 1e-10 needs a tight projection
  o.initial = {flow::InitialType::taylor_green, 1.0, 1.0};
  o.time.end = end;
  o.output.print = false;
  return o;
}

// Records what the loop hands to the field sink.
struct Recorder {
  std::vector<std::pair<std::string, double>> writes;
  std::vector<std::string> names;
  io::FieldSink sink() {
    return [this](const std::string& base, double t, const io::FieldSet& set) {
      writes.emplace_back(base, t);
      names.clear();
      for (const auto& s : set.scalars) names.push_back(s.first);
      for (const auto& v : set.vectors) names.push_back(v.first);
    };
  }
};

}  // namespace

TEST_CASE("Taylor-Green run of a non-Newtonian fluid: no error against the Newtonian vortex") {
  // The vortex decays at the Newtonian rate of flow.viscosity; a Carreau-Yasuda fluid (whose
  // viscosity here is 3-4 times that) must not be measured against it as if it were exact.
  Setup s(8, MPI_COMM_WORLD);
  auto options = tgv_options(0.2);
  auto& cy = options.projection.rheology;
  cy.law = flow::ViscosityLaw::carreau_yasuda;
  cy.mu_0 = 0.05, cy.mu_inf = 0.01, cy.lambda = 1, cy.a = 2, cy.n = 0.5;
  run::RunLoop loop(s.mesh, s.metrics, s.local, options);
  const auto summary = loop.run();
  CHECK(summary.steps > 0);
  CHECK_FALSE(summary.taylor_green);
  options.projection.rheology = {};  // the same run Newtonian: reported
  run::RunLoop newtonian(s.mesh, s.metrics, s.local, options);
  CHECK(newtonian.run().taylor_green);
}

TEST_CASE("Taylor-Green run: exact-solution error, output times, rank independence") {
  Setup s(16, MPI_COMM_WORLD);
  auto options = tgv_options(0.5);
  options.output.interval = 0.2;
  options.output.print = true;  // the progress lines hold collectives too: run them at np 2
  options.output.log_every = 2;
  Recorder rec;
  run::RunLoop loop(s.mesh, s.metrics, s.local, options, rec.sink());
  const auto summary = loop.run();
  REQUIRE(summary.taylor_green);
  const auto& e = *summary.taylor_green;
  MESSAGE("n 16: steps " << summary.steps << " L2 " << e.velocity_l2 << " rel "
                         << e.velocity_l2 / e.exact_l2 << " Linf " << e.velocity_linf << " max div "
                         << summary.max_divergence << " Poisson its "
                         << summary.max_poisson_iterations);
  CHECK(summary.time == doctest::Approx(0.5).epsilon(1e-14));
  // CFL 0.5 with max |u| = 1 and h = 2 pi / 16: dt = 0.196; each output interval 0.2 (< 2 dt)
  // is shared by two steps of 0.1, the last 0.1 to t = 0.5 is one step: 5 steps.
  CHECK(summary.steps == 5);
  // Measured relative L2 error 1.62e-4 (2nd-order in h and dt); twice that catches a wrong
  // initial pressure, decay rate or time bookkeeping, which give errors of O(1e-3) or more.
  CHECK(e.velocity_l2 / e.exact_l2 < 3.2e-4);
  CHECK(e.velocity_l2 > 0);
  // Approximate projection (compact Poisson matrix, wide divergence stencil): the divergence
  // left is O(h^2) (h^2 = 0.154), measured 9.5e-4.
  CHECK(summary.max_divergence < 2e-3);
  // Cubic cells h = 2 pi / 16 and max |u| between 1 (a node sits on the maximum) and its decay
  // exp(-2 nu t) = 0.99 at t = 0.5: the divergence number is max |div| h / max |u| within 1 %.
  const double h = 2 * std::numbers::pi / 16;
  CHECK(summary.max_divergence_number >= summary.max_divergence * h * (1 - 1e-12));
  CHECK(summary.max_divergence_number <= summary.max_divergence * h / 0.99);
  // Where and when: a node of the box, at one of the step times (0.1 .. 0.5).
  const auto& at = summary.max_divergence_position;
  for (int c = 0; c < 2; ++c) CHECK((at[c] >= 0 && at[c] <= 2 * std::numbers::pi));
  CHECK((at.z() >= 0 && at.z() <= 3 * h));
  CHECK(summary.max_divergence_time > 0);
  CHECK(summary.max_divergence_time <= 0.5 + 1e-12);
  double nearest = 1e300;
  for (int i = 0; i < s.local.num_owned; ++i)
    nearest = std::min(nearest, (s.local.position[i] - at).norm());
  CHECK(s.local.comm.min(nearest) < 1e-12);
  // Fields at t = 0, 0.2, 0.4 and the end, with the three fields.
  REQUIRE(rec.writes.size() == 4);
  CHECK(rec.writes[1].second == doctest::Approx(0.2).epsilon(1e-14));
  CHECK(rec.writes[3].second == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(rec.names == std::vector<std::string>{"pressure", "velocity", "vorticity"});

  // The same run on one rank (every rank runs it alone) agrees to 1e-10 of U0.
  Setup serial(16, MPI_COMM_SELF);
  run::RunLoop alone(serial.mesh, serial.metrics, serial.local, options);
  alone.run();
  const auto n = static_cast<mesh::GlobalIndex>(s.metrics.num_nodes());
  const auto a = test::gather_by_dual_node(s.local, test::flatten(loop.state().velocity), 3, n);
  const auto b =
      test::gather_by_dual_node(serial.local, test::flatten(alone.state().velocity), 3, n);
  const double diff = test::max_abs_difference(a, b);
  MESSAGE("np " << s.local.comm.size() << " vs serial: max |du| " << diff);
  CHECK(diff < 1e-10);
}

TEST_CASE("time.land_on_output = false: full steps only, fields at the first step past") {
  Setup s(16, MPI_COMM_WORLD);
  auto options = tgv_options(0.5);
  options.time.dt = 0.125;  // 4 full steps; output times 0.2 and 0.4 fall inside steps 2 and 4
  options.output.interval = 0.2;
  options.time.land_on_output = false;
  Recorder rec;
  run::RunLoop loop(s.mesh, s.metrics, s.local, options, rec.sink());
  const auto summary = loop.run();
  CHECK(summary.steps == 4);
  CHECK(summary.time == doctest::Approx(0.5).epsilon(1e-14));
  // t = 0, then 0.25 (first step at or after 0.2), 0.5 (after 0.4; also the end).
  REQUIRE(rec.writes.size() == 3);
  CHECK(rec.writes[1].second == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(rec.writes[2].second == doctest::Approx(0.5).epsilon(1e-14));

  // Landing on the output times (the default) splits those steps: 0.125, 0.2, 0.3, 0.4, 0.5.
  options.time.land_on_output = true;
  Recorder landing;
  run::RunLoop landed(s.mesh, s.metrics, s.local, options, landing.sink());
  CHECK(landed.run().steps == 5);
  REQUIRE(landing.writes.size() == 4);
  CHECK(landing.writes[1].second == doctest::Approx(0.2).epsilon(1e-14));
}

TEST_CASE("time.land_on: the step before each listed time is shortened to land on it") {
  Setup s(16, MPI_COMM_WORLD);
  auto options = tgv_options(0.5);
  options.time.dt = 0.125;                  // full steps at 0.125, 0.25, 0.375, 0.5
  options.time.land_on = {0.05, 0.3, 0.9};  // sorted as the scene reader does; 0.9 > end: ignored
  std::vector<double> times;
  run::RunLoop loop(s.mesh, s.metrics, s.local, options);
  run::RunHooks hooks;
  hooks.after_step = [&times](const flow::FlowState& state, std::int64_t) {
    times.push_back(state.time);
  };
  loop.set_hooks(hooks);
  const auto summary = loop.run();
  // 0.05 (landed), 0.175, 0.3 (landed), then 0.2 left, less than two steps: 0.4 and 0.5 share it.
  REQUIRE(times.size() == 5);
  CHECK(summary.time == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(times[0] == doctest::Approx(0.05).epsilon(1e-14));
  CHECK(times[1] == doctest::Approx(0.175).epsilon(1e-14));
  CHECK(times[2] == doctest::Approx(0.3).epsilon(1e-14));
  CHECK(times[3] == doctest::Approx(0.4).epsilon(1e-14));
}

TEST_CASE("vorticity of the Taylor-Green field is 2 U0/L sin x sin y to 2nd order") {
  Setup s(32, MPI_COMM_WORLD);
  auto options = tgv_options(0.0);
  run::RunLoop loop(s.mesh, s.metrics, s.local, options);
  flow::TensorField grad;
  flow::VectorField omega;
  flow::gradient(s.local, loop.state().velocity, grad);
  flow::vorticity(grad, omega);
  double worst = 0;
  for (int j = 0; j < s.local.num_owned; ++j) {
    const auto& x = s.local.position[j];
    const Eigen::Vector3d exact(0, 0, 2 * std::sin(x.x()) * std::sin(x.y()));
    worst = std::max(worst, (omega[j] - exact).norm());
  }
  worst = s.local.comm.max(worst);
  // Centred differences on uniform hexahedra differentiate sin exactly up to the factor
  // sin(h)/h, so omega_z = 2 sin x sin y sin(h)/h; the largest error, at the node
  // (pi/2, pi/2), is 2 (1 - sin(h)/h) = h^2/3 + O(h^4).
  const double h = 2 * std::numbers::pi / 32;
  MESSAGE("max vorticity error " << worst);
  CHECK(worst == doctest::Approx(2 * (1 - std::sin(h) / h)).epsilon(1e-8));
}

TEST_CASE("a time step beyond the RK4 stability limit is refused, one below it runs") {
  Setup s(16, MPI_COMM_WORLD);
  auto options = tgv_options(1.0);
  // Uniform hexahedra, h = 2 pi / 16: the viscous rate is 12 nu / h^2 at every node and the
  // convective rate (1/2V) sum |u_jk . S_jk| peaks at the node (pi/2, 0), where u = (1, 0, 0),
  // the x-neighbours have u = cos h and the y-neighbours v = 0: (1 + cos h) / (2 h).
  const double h = 2 * std::numbers::pi / 16;
  const double limit = 1 / ((1 + std::cos(h)) / (2 * h) / flow::rk4_imaginary_limit +
                            12 * 0.01 / (h * h) / flow::rk4_real_limit);
  options.time.dt = 1.02 * limit;
  run::RunLoop refused(s.mesh, s.metrics, s.local, options);
  try {
    refused.run();
    FAIL("a time step above the limit ran");
  } catch (const run::RunError& e) {
    const std::string what = e.what();
    MESSAGE(what);
    CHECK(what.find("time.dt") != std::string::npos);
    CHECK(what.find("stability limit") != std::string::npos);
    // The limit named in the message is the one computed here, to 4 digits.
    const auto at = what.find("stability limit ") + 16;
    CHECK(std::stod(what.substr(at)) == doctest::Approx(limit).epsilon(1e-5));
  }
  options.time.dt = 0.95 * limit;
  options.time.end = 20 * options.time.dt;
  run::RunLoop runs(s.mesh, s.metrics, s.local, options);
  const auto summary = runs.run();
  CHECK(summary.steps == 20);
  // Stable at CFL 2.1: no node's speed grows above the initial U0 = 1 (measured L2 error 10%,
  // the time error of such a large step).
  double fastest = 0;
  for (int j = 0; j < s.local.num_owned; ++j)
    fastest = std::max(fastest, runs.state().velocity[j].norm());
  CHECK(s.local.comm.max(fastest) < 1.0);
  // An adaptive step from a CFL target beyond the limit is refused, naming time.cfl.
  options.time.dt = 0;
  options.time.cfl = 3.5;
  run::RunLoop adaptive(s.mesh, s.metrics, s.local, options);
  CHECK_THROWS_WITH_AS(adaptive.run(), doctest::Contains("lower time.cfl"), run::RunError);
}

TEST_CASE("a blow-up stops the run with a diagnosis after writing the last good state") {
  Setup s(16, MPI_COMM_WORLD);
  auto options = tgv_options(100.0);
  options.time.dt = 2.0;  // 2.3 times the stability limit, let through by the test-only switch
  options.enforce_stability_limit = false;
  options.velocity_limit = 10;  // U0 = 1
  Recorder rec;
  run::RunLoop loop(s.mesh, s.metrics, s.local, options, rec.sink());
  try {
    loop.run();
    FAIL("an unstable run finished");
  } catch (const run::RunError& e) {
    const std::string what = e.what();
    MESSAGE(what);
    CHECK(what.find("velocity") != std::string::npos);
    CHECK(what.find("at node") != std::string::npos);
    CHECK(what.find("(x, y, z)") != std::string::npos);
    CHECK(what.find("last_good.xmf") != std::string::npos);
    CHECK(what.find("--restart RUN_DIR/checkpoints/checkpoint_<step>.h5 --set time.cfl") !=
          std::string::npos);
  }
  // No output interval: the only field write is the last good state, one step before the end.
  REQUIRE(rec.writes.size() == 1);
  CHECK(rec.writes[0].first == "last_good");
  CHECK(rec.writes[0].second == doctest::Approx(loop.state().time - 2.0));
}

TEST_CASE("the state guard names the field and the position of a non-finite node") {
  Setup s(8, MPI_COMM_WORLD);
  flow::VectorField u(s.local.num_local(), Eigen::Vector3d(0.5, 0, 0));
  flow::ScalarField p(s.local.num_local(), 0.0);
  CHECK(flow::find_bad_state(s.local, u, p, 1.0).empty());
  // Two bad nodes: the one with the lower dual-node number is reported on every rank.
  const Eigen::Vector3d target = s.metrics.position[5], other = s.metrics.position[40];
  for (int j = 0; j < s.local.num_owned; ++j) {
    if (s.local.dual_node[j] == 5) p[j] = std::nan("");
    if (s.local.dual_node[j] == 40) u[j].x() = INFINITY;
  }
  const auto what = flow::find_bad_state(s.local, u, p, 1.0);
  MESSAGE(what);
  CHECK(what.find("pressure is not finite") != std::string::npos);
  CHECK(what.find("node 5 ") != std::string::npos);
  CHECK(what.find(fmt::format("({:.6g}, {:.6g}, {:.6g})", target.x(), target.y(), target.z())) !=
        std::string::npos);
  (void)other;
}

TEST_CASE("non-periodic patches without a boundary condition are refused, naming them") {
  Setup s(8, MPI_COMM_WORLD, /*periodic_z=*/false);
  try {
    run::RunLoop(s.mesh, s.metrics, s.local, tgv_options(1.0));
    FAIL("a mesh with open patches and no conditions ran");
  } catch (const run::RunError& e) {
    CHECK(std::string(e.what()).find("patches 'zmin', 'zmax' of the mesh have no boundary "
                                     "condition") != std::string::npos);
    CHECK(e.key() == "boundary");
  }
}

TEST_CASE("scene keys become run options") {
  const auto scene = scene::parse_scene(R"(
[mesh]
source = "box"
[flow]
density = 1000.0
viscosity = 1e-3
[time]
end = 2.0
cfl = 0.4
[initial]
type = "taylor_green"
[initial.taylor_green]
velocity = 0.1
length = 0.01
[output]
interval = 5
interval_unit = "steps"
fields = ["vorticity"]
)",
                                        "s.toml");
  const auto o = scene::flow_run_options(scene, "dir");
  CHECK(o.projection.viscosity == doctest::Approx(1e-6));
  CHECK(o.time.cfl == 0.4);
  CHECK(o.initial.length == 0.01);
  CHECK(o.output.interval_in_steps);
  CHECK(o.output.vorticity);
  CHECK_FALSE(o.output.velocity);
  CHECK(o.output.log_every == 10);
  CHECK(o.time.land_on_output);  // the defaults
  CHECK_FALSE(o.projection.stiffness_viscous);
  const auto full_steps = scene::parse_scene(
      "[mesh]\nsource = \"box\"\n[time]\nland_on_output = false\n[flow]\n"
      "viscous_weights = \"stiffness\"\n",
      "l.toml");
  const auto f = scene::flow_run_options(full_steps, "dir");
  CHECK_FALSE(f.time.land_on_output);
  CHECK(f.projection.stiffness_viscous);
  const auto fractional = scene::parse_scene(
      "[mesh]\nsource = \"box\"\n[output]\ninterval = 2.5\ninterval_unit = \"steps\"\n", "f.toml");
  CHECK_THROWS_WITH_AS(scene::flow_run_options(fractional, "dir"),
                       doctest::Contains("f.toml:4:1: key 'output.interval'"), scene::SceneError);
}

TEST_CASE("time.scheme and time.project_stages become run options; unknown schemes are refused") {
  const auto defaults =
      scene::flow_run_options(scene::parse_scene("[mesh]\nsource = \"box\"\n", "d.toml"), "dir");
  CHECK(defaults.projection.time_scheme == flow::TimeScheme::rk4_jameson);
  CHECK_FALSE(defaults.projection.project_stages);
  const auto classic = scene::flow_run_options(
      scene::parse_scene("[mesh]\nsource = \"box\"\n[time]\nscheme = \"rk4_classic\"\n"
                         "project_stages = true\n",
                         "c.toml"),
      "dir");
  CHECK(classic.projection.time_scheme == flow::TimeScheme::rk4_classic);
  CHECK(classic.projection.project_stages);
  CHECK_THROWS_WITH_AS(
      scene::parse_scene("[mesh]\nsource = \"box\"\n[time]\nscheme = \"rk4\"\n", "u.toml"),
      doctest::Contains("u.toml:4:10: key 'time.scheme': unknown value \"rk4\" (accepted: "
                        "\"rk4_jameson\", \"rk4_classic\")"),
      scene::SceneError);
}

TEST_CASE("the 3D Taylor-Green initial state: closed-form pressure and a consistent start") {
  const flow::TaylorGreen3d tg{0.7, 0.4, 1.3};
  // lap p = -rho (du_i/dx_j)(du_j/dx_i) by central differences (h = 1e-3 L: error ~ 1e-7).
  const double h = 1e-3 * tg.length;
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(-0.5, 0.9, 0.05),
                                   Eigen::Vector3d(1.1, -0.7, 0.6)}) {
    Eigen::Matrix3d grad;  // grad(i, j) = du_i/dx_j
    double lap = 0;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      grad.col(j) = (tg.velocity(x + e) - tg.velocity(x - e)) / (2 * h);
      lap += (tg.pressure(x + e) - 2 * tg.pressure(x) + tg.pressure(x - e)) / (h * h);
    }
    const double source = -tg.rho * (grad.array() * grad.transpose().array()).sum();
    const double scale = tg.rho * tg.u0 * tg.u0 / (tg.length * tg.length);
    CHECK(std::abs(lap - source) < 1e-5 * scale);
    CHECK(std::abs(grad.trace()) < 1e-6 * tg.u0 / tg.length);  // divergence-free
  }
  // On the periodic 16^3 box of side 2 pi: the run loop starts from the closed form, and its
  // first pressure increment is a small fraction of the pressure (measured 0.035: the O(h^2)
  // difference of the discrete pressure; at rest with p = 0 it would be 1).
  auto box = test::periodic_box("hexa", 16);
  box.length = Eigen::Vector3d::Constant(2 * std::numbers::pi);
  const auto mesh = mesh::generate_box(box);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  scene::RunOptions o;
  o.projection.viscosity = 1.0 / 1600;
  o.initial = {flow::InitialType::taylor_green_3d, 1.0, 1.0};
  o.time.end = o.time.dt = 0.01;
  o.output.print = false;
  run::RunLoop loop(mesh, metrics, local, o);
  const flow::TaylorGreen3d exact{1.0, 1.0, 1.0};
  double worst = 0, p_max = 0;
  for (int j = 0; j < local.num_owned; ++j) {
    worst = std::max(worst, (loop.state().velocity[j] - exact.velocity(local.position[j])).norm());
    worst = std::max(worst, std::abs(loop.state().pressure[j] - exact.pressure(local.position[j])));
    p_max = std::max(p_max, std::abs(loop.state().pressure[j]));
  }
  CHECK(local.comm.max(worst) == 0);
  loop.run();
  double dp = 0;
  for (int j = 0; j < local.num_owned; ++j)
    dp = std::max(dp, std::abs(loop.pressure_increment()[j]));
  dp = local.comm.max(dp), p_max = local.comm.max(p_max);
  MESSAGE("taylor_green_3d 16^3: max |dp| / max |p| after one step = " << dp / p_max);
  CHECK(dp < 0.1 * p_max);
}

TEST_CASE("taylor_green_3d needs a mesh periodic in z too") {
  const auto scene = scene::parse_scene(R"([mesh]
source = "box"
[initial]
type = "taylor_green_3d"
[initial.taylor_green]
velocity = 1.0
length = 1.0
)",
                                        "tg3.toml");
  mesh::BoxSpec box;
  box.cells = {4, 4, 4};
  box.length = Eigen::Vector3d::Constant(2 * std::numbers::pi);
  box.periodic = {true, true, true};
  CHECK_NOTHROW(scene::check_initial_state(scene, mesh::generate_box(box)));
  box.periodic = {true, true, false};
  CHECK_THROWS_WITH_AS(
      scene::check_initial_state(scene, mesh::generate_box(box)),
      doctest::Contains("the Taylor-Green vortex is periodic in z, the mesh is not "
                        "(no periodic pair along z) (accepted: a mesh periodic in "
                        "x, y and z)"),
      scene::SceneError);
}

TEST_CASE("[forcing], initial.cyclic_sines and time.stability_fraction from a scene") {
  const auto scene = scene::parse_scene(R"(
[mesh]
source = "box"
[forcing]
type = "kolmogorov"
force = [2.0, 0.0, 0.0]
wavelength = 1.0
[initial]
type = "cyclic_sines"
[initial.cyclic_sines]
velocity = 0.1
length = 0.5
[time]
stability_fraction = 0.8
[poisson]
periodic_damping = true
)",
                                        "k.toml");
  const auto o = scene::flow_run_options(scene, "dir");
  CHECK(o.forcing.type == flow::ForcingSpec::Type::kolmogorov);
  CHECK(o.forcing.across == Eigen::Vector3d::UnitY());  // the default
  CHECK(o.initial.type == flow::InitialType::cyclic_sines);
  CHECK(o.initial.length == 0.5);
  CHECK(o.time.stability_fraction == 0.8);
  CHECK(o.projection.periodic_pressure_damping);

  // On 20 % perturbed tetrahedra the sampled sine has a discrete mean; the force has none, and
  // away from it the nodal values are F sin(2 pi y) to that mean (|mean| << F).
  mesh::BoxSpec box;
  box.cells = {6, 6, 6};
  box.cell_type = mesh::BoxCellType::tetra;
  box.perturbation = 0.2;
  box.periodic = {true, true, true};
  const auto mesh = mesh::generate_box(box);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  const auto f = flow::forcing_density(local, o.forcing);
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  double deviation = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    net += local.volume[i] * f[i];
    deviation =
        std::max(deviation,
                 std::abs(f[i].x() - 2.0 * std::sin(2 * std::numbers::pi * local.position[i].y())));
  }
  for (int c = 0; c < 3; ++c) CHECK(std::abs(local.comm.sum(net[c])) < 1e-14);
  CHECK(deviation > 0);     // the mean was there to remove ...
  CHECK(deviation < 2e-2);  // ... and it is small against F = 2

  // The time step at the stability fraction: 0.8 of the limit, whatever cfl and fourier say.
  Setup s(8, MPI_COMM_WORLD);
  auto run = tgv_options(100.0);
  run.time.stability_fraction = 0.8;
  run.time.max_steps = 1;
  run::RunLoop loop(s.mesh, s.metrics, s.local, run);
  std::vector<double> scratch;
  const double limit = 1.0 / flow::stability_rates(s.local, flow::laplacian_weights(s.local), 0.01,
                                                   loop.state().velocity, scratch)
                                 .stability;
  const auto summary = loop.run();
  CHECK(summary.time == doctest::Approx(0.8 * limit).epsilon(1e-12));

  auto bad = [](const std::string& forcing) {
    try {
      scene::flow_run_options(
          scene::parse_scene("[mesh]\nsource = \"box\"\n[forcing]\n" + forcing, "b.toml"), "dir");
    } catch (const scene::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(bad("type = \"kolmogorov\"\nforce = [1.0, 0.0, 0.0]\nwavelength = 1.0\n"
            "across = [0.0, 0.0, 0.0]\n")
            .find("key 'forcing.across': the direction must be a non-zero") != std::string::npos);
  CHECK(bad("type = \"kolmogorov\"\nforce = [1.0, 0.0, 0.0]\n").find("forcing.wavelength") !=
        std::string::npos);
  CHECK(bad("type = \"uniform\"\nforce = [1.0, 0.0, 0.0]\nwavelength = 1.0\n")
            .find("forcing.wavelength") != std::string::npos);  // no effect with uniform
}

TEST_CASE("set_initial_velocity replaces the initial condition; time.steady_tolerance stops") {
  Setup s(8, MPI_COMM_WORLD);
  auto options = tgv_options(100.0);
  options.time.dt = 0.1;
  options.time.steady_tolerance = 1e-9;  // m/s^2
  auto at_rest = options;
  at_rest.initial.type = flow::InitialType::rest;  // p = 0
  run::RunLoop loop(s.mesh, s.metrics, s.local, at_rest);
  // The Taylor-Green velocity at rest pressure: the first step moves the fluid.
  flow::VectorField vortex_velocity(s.local.num_local());
  const flow::TaylorGreen tg{1.0, 1.0, 0.01, 1.0};
  for (int i = 0; i < s.local.num_local(); ++i)
    vortex_velocity[i] = tg.velocity(s.local.position[i], 0.0);
  loop.set_initial_velocity(vortex_velocity);
  CHECK(loop.state().velocity[0] == vortex_velocity[0]);
  // And a fluid at rest stays at rest: steady after one step.
  loop.set_initial_velocity(flow::VectorField(s.local.num_local(), Eigen::Vector3d::Zero()));
  const auto summary = loop.run();
  CHECK(summary.steady);
  CHECK(summary.steps == 1);
  CHECK(summary.change_rate < 1e-9);
  // The vortex itself decays at 2 nu u: |du/dt| ~ 0.02 m/s^2 is far from steady at 1e-3.
  options.time.steady_tolerance = 1e-3;
  options.time.max_steps = 3;
  run::RunLoop vortex(s.mesh, s.metrics, s.local, options);
  const auto decaying = vortex.run();
  CHECK_FALSE(decaying.steady);
  CHECK(decaying.steps == 3);
  CHECK(decaying.change_rate == doctest::Approx(0.02).epsilon(0.1));
  CHECK_THROWS_AS(vortex.set_initial_velocity(flow::VectorField(3)), run::RunError);
}

TEST_CASE("initial.plane_poiseuille: the developed channel profile at t = 0") {
  const auto scene_with = [](const std::string& direction) {
    return scene::parse_scene(R"(
[mesh]
source = "box"
[initial]
type = "plane_poiseuille"
[initial.plane_poiseuille]
mean_velocity = 0.5
width = 6.283185307179586
point = [0.0, 0.0, 0.0]
direction = )" + direction + "\n",
                              "p.toml");
  };
  auto o = scene::flow_run_options(scene_with("[2.0, 0.0, 0.0]"), "dir");
  CHECK(o.initial.type == flow::InitialType::plane_poiseuille);
  CHECK(o.initial.velocity == 0.5);
  CHECK(o.initial.across == Eigen::Vector3d::UnitY());  // the default
  o.output.print = false;
  o.projection.poisson.tolerance = 1e-10;
  Setup s(6, MPI_COMM_WORLD);
  run::RunLoop loop(s.mesh, s.metrics, s.local, o);
  double peak = 0;
  for (int j = 0; j < s.local.num_local(); ++j) {
    const double y = s.local.position[j].y() / (2 * std::numbers::pi);
    const double u = y > 0 && y < 1 ? 3.0 * y * (1 - y) : 0.0;
    CHECK((loop.state().velocity[j] - Eigen::Vector3d(u, 0, 0)).norm() < 1e-14);
    peak = std::max(peak, loop.state().velocity[j].x());
  }
  CHECK(peak == doctest::Approx(0.75));  // 1.5 U at mid-width (a node row there)
  // A direction along `across` is refused, naming the key.
  CHECK_THROWS_WITH_AS(
      scene::flow_run_options(scene_with("[0.0, 1.0, 0.0]"), "dir"),
      doctest::Contains("key 'initial.plane_poiseuille.across': across must be perpendicular"),
      scene::SceneError);
}
