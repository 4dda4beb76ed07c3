// One Turek–Hron FSI run; see fsi_run.hpp.
#include "validation/turek_hron_fsi/fsi_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>
#include <stdexcept>

#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "flow/run_diagnostics.hpp"
#include "ibm/immersed_structure.hpp"
#include "mesh/cylinder_channel_generator.hpp"
#include "structure/material.hpp"
#include "structure/mesh_generators.hpp"
#include "validation/dfg_cylinder/cylinder_channel_flow.hpp"

namespace valsalva::validation {

namespace {

using Vec = Eigen::Vector3d;
using Clock = std::chrono::steady_clock;

// Benchmark geometry (turek_hron_parameters.csv header).
constexpr double kLength = 2.5, kHeight = 0.41, kCx = 0.2, kCy = 0.2, kRadius = 0.05;
constexpr double kBarEnd = 0.6, kBarHalf = 0.01;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Q2 elements of size ~size_near (markers h/2 apart in the plane, the usual no-leak spacing);
// in z, element nodes about size_near apart are enough for a z-invariant state.
structure::SolidMesh bar_mesh(double size, double depth, int layers) {
  const double x_clamp = kCx + std::sqrt(kRadius * kRadius - kBarHalf * kBarHalf);
  const int nx = std::max(1, static_cast<int>(std::lround((kBarEnd - x_clamp) / size)));
  const int ny = std::max(1, static_cast<int>(std::lround(2 * kBarHalf / size)));
  const int nz = std::max(2, layers / 2);
  auto m = structure::structured_block(structure::HexOrder::q2, {nx, ny, nz}, [&](const Vec& s) {
    const double y = kCy - kBarHalf + 2 * kBarHalf * s[1];
    const double x0 = kCx + std::sqrt(kRadius * kRadius - (y - kCy) * (y - kCy));
    return Vec(x0 + s[0] * (kBarEnd - x0), y, depth * s[2]);
  });
  m.source = fmt::format("<Turek-Hron bar {}x{}x{}>", nx, ny, nz);
  return m;
}

int tip_node(const structure::SolidMesh& m) {
  for (int n : m.node_set("u1"))
    if (std::abs(m.X(1, n) - kCy) < 1e-12 && m.X(2, n) == 0) return n;
  throw std::logic_error("turek_hron_fsi: the bar mesh has no node at point A");
}

// Inflow Q(t) with the benchmark's smooth start, as a table (Waveform tables repeat with their
// span, so the last row is far beyond any run).
flow::Waveform inflow(double q, double ramp) {
  flow::Waveform w;
  if (ramp <= 0) {
    w.mean = q;
    return w;
  }
  w.kind = flow::Waveform::Kind::table;
  const int n = 200;
  for (int i = 0; i <= n; ++i) {
    const double t = ramp * i / n;
    w.t.push_back(t);
    w.q.push_back(q * 0.5 * (1 - std::cos(std::numbers::pi * t / ramp)));
  }
  w.t.push_back(1e6);
  w.q.push_back(q);
  return w;
}

}  // namespace

FsiResult run_fsi(const Context& ctx, const FsiSpec& spec) {
  const auto t0 = Clock::now();
  const auto& p = spec.p;
  const double rho = p.rho_f, nu = p.nu_f;
  if (!(p.E_s > 0) || !(p.U_bar > 0))
    throw std::invalid_argument("turek_hron_fsi: the case needs an elastic bar and an inflow");

  io::CylinderChannelSpec mesh_spec;
  mesh_spec.length = kLength;
  mesh_spec.height = kHeight;
  mesh_spec.centre_x = kCx;
  mesh_spec.centre_y = kCy;
  mesh_spec.diameter = 2 * kRadius;
  mesh_spec.size_near = spec.level.size_near;
  mesh_spec.size_far = spec.level.size_far;
  mesh_spec.layers = spec.level.layers;
  mesh_spec.thickness = spec.level.layers * spec.level.size_near;
  // The bar and its swing (FSI3 tip amplitude 0.035) at size_near.
  mesh_spec.box_size = spec.level.size_near;
  mesh_spec.box_x0 = kCx;
  mesh_spec.box_x1 = kBarEnd + 0.06;
  mesh_spec.box_y0 = kCy - 0.06;
  mesh_spec.box_y1 = kCy + 0.06;
  mesh_spec.box_transition = 0.15;
  const double depth = mesh_spec.thickness;
  auto mesh = io::generate_cylinder_channel_mesh(mesh_spec);
  mesh.periodic.push_back({"front", "back", Vec(0, 0, depth)});
  const auto metrics = flow::compute_dual_metrics(mesh);
  auto local = flow::distribute(mesh, metrics, ctx.comm, {4, "metis"});

  auto channel = make_cylinder_channel_flow(mesh, metrics, local, rho, nu,
                                            inflow(p.U_bar * kHeight * depth, spec.ramp));
  auto& solver = *channel.solver;

  const auto bar = bar_mesh(spec.level.size_near, depth, spec.level.layers);
  const auto material = structure::make_st_venant_kirchhoff(p.E_s, p.nu_s);
  ibm::ImmersedOptions ib_options;
  ib_options.fluid_density = rho;
  ib_options.transfer.kernel = spec.kernel;
  if (spec.per_step) ib_options.mode = ibm::CouplingMode::per_step;
  ib_options.box =
      ibm::PeriodicBox{Vec::Zero(), Vec(kLength, kHeight, depth), {false, false, true}};
  ibm::ImmersedStructure ib(local, ib_options);
  // Tether: a node spring of E times the marker spacing, about the bar's own nodal stiffness,
  // so the clamp is as stiff as the bar without lowering the coupling bound much.
  ib.add_body(bar, *material, {"bar", {"u0"}, p.E_s * spec.level.size_near / 2});
  const int A = tip_node(bar);
  if (spec.initial_bend != 0) {
    Eigen::Matrix3Xd x = bar.X;
    const double x_clamp = kCx + std::sqrt(kRadius * kRadius - kBarHalf * kBarHalf);
    for (int a = 0; a < x.cols(); ++a) {
      const double s = std::max(0.0, (bar.X(0, a) - x_clamp) / (kBarEnd - x_clamp));
      x(1, a) += spec.initial_bend * s * s;
    }
    ib.set_positions(x);
  }
  flow::VectorField density(local.num_local(), Vec::Zero());
  auto hook = ib.body_force();
  double hook_seconds = 0;
  solver.set_body_force([&](int k, double t, const flow::VectorField& u, flow::VectorField& f) {
    const auto h0 = Clock::now();
    hook(k, t, u, f);
    hook_seconds += seconds_since(h0);
    if (k == 3) density = f;  // the density that goes with ib.forces() (stage-3 forces)
  });

  flow::FlowState state;
  state.velocity.assign(local.num_local(), Vec::Zero());
  state.pressure.assign(local.num_local(), 0.0);
  if (spec.ramp <= 0)  // developed channel profile everywhere (a shortcut to the steady state)
    for (int i = 0; i < local.num_local(); ++i) {
      const double s = local.position[i].y() / kHeight;
      state.velocity[i] = Vec(6 * p.U_bar * s * (1 - s), 0, 0);
    }
  impose_initial_boundary_values(*channel.bc, state);

  FsiResult r;
  r.nodes = local.global_nodes;
  r.markers = ib.num_markers();
  r.slab = depth;
  r.ranks = local.comm.size();
  flow::TensorField grad;
  auto sample = [&]() {
    const Vec cyl = cylinder_force(local, solver, state, rho, nu, grad, &density);
    const Vec on_bar = -ib.total_force(0);
    const Vec total = (cyl + on_bar) / depth;
    const Vec uA = ib.positions().col(A) - bar.X.col(A);
    r.samples.push_back(
        {state.time, uA.x(), uA.y(), total.x(), total.y(), on_bar.x() / depth, on_bar.y() / depth});
  };

  const auto weights = flow::laplacian_weights(local);
  std::vector<double> scratch;
  r.dt_bound = ib.stable_time_step();
  double dt = 0, next_sample = 0, next_bound = 0.5, next_steady = spec.steady_window;
  FsiSample at_window{};
  const auto loop_start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  while (state.time < spec.t_end - 1e-12 && (spec.max_steps <= 0 || r.steps < spec.max_steps)) {
    if (r.steps % 10 == 0) {
      const double fluid =
          0.5 / flow::stability_rates(local, weights, nu, state.velocity, scratch).stability;
      dt = std::min(spec.dt_fraction * r.dt_bound, fluid);
      ib.check_time_step(dt);
    }
    solver.step(state, std::min(dt, spec.t_end - state.time));
    ib.finish_step(state);
    ++r.steps;
    r.dt = std::max(r.dt, dt);
    if (state.time >= next_sample - 1e-12) {
      sample();
      next_sample += spec.sample_interval;
      for (int a = 0; a < ib.num_markers(); ++a)
        r.max_w = std::max(r.max_w, std::abs(ib.velocities()(2, a)));
    }
    if (state.time >= next_bound) {  // the tangent stiffness follows the deflection
      r.dt_bound = ib.stable_time_step();
      next_bound += 0.5;
    }
    if (spec.steady_window > 0 && state.time >= next_steady - 1e-12) {
      sample();
      const auto& s = r.samples.back();
      r.steady_change =
          std::max(std::abs(s.drag / at_window.drag - 1), std::abs(s.uy / at_window.uy - 1));
      at_window = s;
      next_steady += spec.steady_window;
      if (local.comm.rank() == 0)
        fmt::print("  t {:.3f}: drag {:.5f} lift {:.5f} uy_A {:.5e} (change {:.2e})\n", s.t, s.drag,
                   s.lift, s.uy, r.steady_change);
      if (r.steady_change < spec.steady_tolerance) break;
    }
  }
  r.loop_wall = seconds_since(loop_start);
  r.loop_cpu = local.comm.max(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
  sample();
  // Force balance of the spreading: sum_j V_j f_j over all fluid nodes = sum_a F_a.
  Vec spread = Vec::Zero();
  for (int i = 0; i < local.num_owned; ++i) spread += local.volume[i] * density[i];
  for (int d = 0; d < 3; ++d) spread[d] = local.comm.sum(spread[d]);
  r.balance_error = (spread - ib.total_force(0)).norm() / ib.total_force(0).norm();
  r.ib_hook_seconds = hook_seconds;
  r.wall = seconds_since(t0);

  if (spec.profile) {  // the pieces of one stage, on a transfer of our own at the same markers
    ibm::DiracTransfer transfer(local, ib_options.transfer);
    Eigen::Matrix3Xd x = ib.positions(), f(3, x.cols());
    for (int a = 0; a < x.cols(); ++a) x(2, a) -= depth * std::floor(x(2, a) / depth);
    std::vector<Vec> markers(x.cols()), values(x.cols()), forces(x.cols());
    for (int a = 0; a < x.cols(); ++a) markers[a] = x.col(a);
    flow::VectorField field = state.velocity, out(local.num_local());
    const int reps = 5;
    auto time = [&](auto&& work) {
      const auto s0 = Clock::now();
      for (int i = 0; i < reps; ++i) work();
      return local.comm.max(seconds_since(s0) / reps);
    };
    r.t_locate = time([&] { transfer.locate(markers); });
    r.t_spread = time([&] { transfer.spread(forces, out); });
    r.t_interp = time([&] { transfer.interpolate(field, values); });
    r.t_forces = time([&] { ib.body(0).forces(ib.positions(), f); });
  }
  return r;
}

}  // namespace valsalva::validation
