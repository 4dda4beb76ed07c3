// DFG benchmark "flow around a cylinder", case 2D-1 (Schäfer & Turek, Notes Numer. Fluid Mech. 52,
// 1996; reference values validation/refdata/dfg_cylinder_benchmark): channel 2.2 x 0.41,
// cylinder D = 0.1 at (0.2, 0.2), rho = 1, nu = 1e-3, parabolic inflow with U_max = 0.3
// (U_mean = 0.2, Re = 20), do-nothing outflow (pressure outlet p = 0), steady. Here as a periodic
// slab of tetrahedra (io/cylinder_channel_generator) on three levels of refinement, run to
// steady state with the largest admissible RK4 step. Measured: c_D, c_L from the consistent
// residual force on the cylinder (flow/wall_force.hpp), dp = p(0.15, 0.2) - p(0.25, 0.2) by
// the probes; asserted on the finest level against the 1996 intervals; a 3-level table in
// dfg_2d1.csv.
#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/run_diagnostics.hpp"
#include "io/cylinder_channel_generator.hpp"
#include "io/probes.hpp"
#include "validation/case.hpp"
#include "validation/dfg_cylinder/cylinder_channel_flow.hpp"

namespace valsalva::validation {

namespace {

// Fraction of the RK4 stability limit (flow/run_diagnostics.hpp) used as the time step: at 0.9
// the coarse level still oscillates at t = 12 (c_D 6.36, changing by 0.23 per time unit).
constexpr double kSigma = 0.5;

struct Level {
  double size_near, size_far;
};

struct Result {
  double cd = 0, cl = 0, dp = 0, change = 0, time = 0, wall = 0;
  long nodes = 0;
  int steps = 0;
};

Result run_level(const Context& ctx, const Level& level, double t_end) {
  const auto t0 = MPI_Wtime();
  const double rho = 1, nu = 1e-3, u_mean = 0.2, d = 0.1, height = 0.41;
  io::CylinderChannelSpec spec;
  spec.size_near = level.size_near;
  spec.size_far = level.size_far;
  spec.thickness = 3 * level.size_near;
  auto mesh = io::generate_cylinder_channel_mesh(spec);
  mesh.periodic.push_back({"front", "back", Eigen::Vector3d(0, 0, spec.thickness)});
  const auto metrics = flow::compute_dual_metrics(mesh);
  const auto local = flow::distribute(mesh, metrics, ctx.comm);

  flow::Waveform inflow;
  inflow.mean = u_mean * height * spec.thickness;
  auto channel = make_cylinder_channel_flow(mesh, metrics, local, rho, nu, inflow);
  auto& solver = *channel.solver;

  flow::FlowState state;
  state.velocity.assign(local.num_local(), Eigen::Vector3d::Zero());
  state.pressure.assign(local.num_local(), 0.0);
  impose_initial_boundary_values(*channel.bc, state);

  const double zc = spec.thickness / 2;
  io::Probes probes(
      mesh, metrics, local,
      {{"front", Eigen::Vector3d(0.15, 0.2, zc)}, {"back", Eigen::Vector3d(0.25, 0.2, zc)}});
  flow::TensorField grad;
  auto coefficients = [&](Result& r) {
    const Eigen::Vector3d f = cylinder_force(local, solver, state, rho, nu, grad) / spec.thickness;
    const double q = 0.5 * rho * u_mean * u_mean * d;
    r.cd = f.x() / q;
    r.cl = f.y() / q;
    const auto p = probes.sample(state);
    r.dp = p[3] - p[7];
  };

  const auto weights = flow::laplacian_weights(local);
  std::vector<double> scratch;
  Result r, previous;
  double dt = 0, next_check = 1.0;
  while (state.time < t_end - 1e-12) {
    if (r.steps % 10 == 0)
      dt = kSigma / flow::stability_rates(local, weights, nu, state.velocity, scratch).stability;
    solver.step(state, std::min(dt, t_end - state.time));
    ++r.steps;
    if (state.time >= next_check - 1e-12) {  // convergence history once per time unit
      previous = r;
      coefficients(r);
      r.change = std::abs(r.cd - previous.cd);
      next_check += 1.0;
    }
  }
  coefficients(r);
  r.change = std::abs(r.cd - previous.cd);
  r.time = state.time;
  r.nodes = local.global_nodes;
  r.wall = MPI_Wtime() - t0;
  return r;
}

void run_dfg(const Context& ctx, Report& report) {
  const std::vector<Level> levels =
      ctx.quick ? std::vector<Level>{{0.02, 0.06}}
                : std::vector<Level>{{0.02, 0.06}, {0.01, 0.04}, {0.005, 0.02}};
  const double t_end = 12.0;
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::ofstream csv;
  if (rank == 0) {
    csv.open(ctx.out_dir / "dfg_2d1.csv");
    csv << "size_near,size_far,nodes,steps,t_end,c_D,c_L,dp,c_D_change_last_unit,wall_s\n";
  }
  Result r;
  for (const auto& level : levels) {
    r = run_level(ctx, level, t_end);
    if (rank == 0) {
      csv << fmt::format("{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.3e},{:.1f}\n", level.size_near,
                         level.size_far, r.nodes, r.steps, r.time, r.cd, r.cl, r.dp, r.change,
                         r.wall);
      csv.flush();
      fmt::print(
          "dfg 2D-1 size {} / {}: {} nodes, {} steps to t = {}: c_D {:.5f} c_L {:.5f} dp {:.5f} "
          "(c_D change over the last time unit {:.2e}), {:.0f} s\n",
          level.size_near, level.size_far, r.nodes, r.steps, r.time, r.cd, r.cl, r.dp, r.change,
          r.wall);
    }
  }
  // Finest level against the 1996 intervals (full case). The quick case runs the coarse level
  // (1545 nodes, 3 s) and checks it is in range: measured c_D 5.95 (+6.6 %), dp 0.1265
  // (+7.6 %), first-order-looking convergence from level 1 to 2 (see dfg_2d1.csv).
  if (!ctx.quick) {
    report.add("c_D (finest level, interval 5.57..5.59)", r.cd, 5.58, 0.01);
    report.add("c_L (finest level, interval 0.0104..0.0110)", r.cl, 0.0107, 0.0003);
    report.add("dp (finest level, interval 0.1172..0.1176)", r.dp, 0.1174, 0.0002);
  } else {
    report.add("c_D coarse level within 10 % of 5.5795", r.cd, 5.5795, 0.56);
    report.add("dp coarse level within 10 % of 0.11752", r.dp, 0.11752, 0.0118);
  }
}

}  // namespace

Case dfg_cylinder_case() {
  return {"dfg_cylinder",
          "DFG flow around a cylinder 2D-1 (Re 20): c_D, c_L, dp on three tetrahedral slab meshes",
          run_dfg};
}

}  // namespace valsalva::validation
