// Poiseuille flow in a streamwise-periodic pipe (issue 22, periodic domains driven like the
// experiments drive them): validation/poiseuille_pipe/poiseuille_pipe.toml (a prescribed mean
// pressure gradient, [forcing] uniform) and poiseuille_pipe_flow_rate.toml (a prescribed flow
// rate, [forcing] flow_rate: flow/flow_rate_control.hpp) run by run::Simulation on
// mesh.source = "periodic_pipe" (a triangulated disk extruded into 3 identical layers, split
// into tetrahedra), the metrics read from the run's outputs (probes.csv, sections.csv,
// wall_shear_history.csv, log.csv) and its final state:
// - the steady profile u(r) = F / (4 mu) (R^2 - r^2) against the nodal velocities (L2 over the
//   nodes / u_max) and its order (the P1 Laplacian of the triangulated disk and its polygonal
//   wall: 2nd order);
// - the wall shear stress of [wall_shear] against tau_w = F R / 2: its mean over the wall nodes
//   (the steady momentum balance, exact to round-off) and its largest nodal deviation (the
//   residual-force distribution over the wall nodes of Gmsh's disk, reported);
// - the flux Q_h(F) of the pressure-driven run through the section against pi R^2 u_max / 2 and
//   its order;
// - the start-up from rest at the axis against the series (separation of variables in r; e.g.
//   Batchelor, An Introduction to Fluid Dynamics, sec. 4.3, or Pozrikidis, Introduction to
//   Theoretical and Computational Fluid Dynamics, 2nd ed., sec. 6.14)
//     u(0, t) = u_max - 8 u_max sum_n exp(-l_n^2 nu t / R^2) / (l_n^3 J1(l_n)),  J0(l_n) = 0,
//   at t = tau/2, tau, 2 tau, tau = R^2 / (l_1^2 nu);
// - the flow-rate drive: the flux through the controlled section against its target at every
//   step, through a second section after the transient, the force it settles at against the
//   pressure-driven run (the discrete steady problem is linear in F, so the force that carries
//   Q is F Q / Q_h(F), Q_h(F) the flux of the pressure-driven run on the same mesh) and against
//   the exact 8 mu Q / (pi R^4).
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "run/simulation.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double kRadius = 0.005, kRho = 1100, kMu = 3.6e-3, kForce = 57.6;  // SI
constexpr double kUmax = kForce * kRadius * kRadius / (4 * kMu);             // 0.1 m/s
constexpr double kFlowRate = std::numbers::pi * kRadius * kRadius * kUmax / 2;

double steady_velocity(double r) {
  return kForce / (4 * kMu) * (kRadius * kRadius - r * r);
}

// The n-th positive zero of J0 by Newton's method from McMahon's estimate (n - 1/4) pi.
double bessel_j0_zero(int n) {
  double x = (n - 0.25) * std::numbers::pi;
  for (int it = 0; it < 50; ++it) {
    const double dx = std::cyl_bessel_j(0.0, x) / -std::cyl_bessel_j(1.0, x);
    x -= dx;
    if (std::abs(dx) < 1e-15 * x) break;
  }
  return x;
}

double viscous_time() {
  const double l1 = bessel_j0_zero(1);
  return kRadius * kRadius / (l1 * l1 * kMu / kRho);
}

// The start-up series at the axis; 200 terms: at t >= tau/2 the 200th is below e^-5000.
double startup_axis(double t) {
  const double nu = kMu / kRho;
  double u = kUmax;
  for (int n = 1; n <= 200; ++n) {
    const double l = bessel_j0_zero(n);
    u -= 8 * kUmax * std::exp(-l * l * nu * t / (kRadius * kRadius)) /
         (l * l * l * std::cyl_bessel_j(1.0, l));
  }
  return u;
}

struct Level {
  int n = 16;  // mesh size D / n
  bool flow_rate = false;
  double profile_error = 0, wss_error = 0, wss_nodal = 0, startup_error = 0;
  double flux = 0;                     // the cut's flux at the end, m^3/s
  double held = 0, held_other = 0;     // flow rate: max |Q - target| / target
  double force = 0, force_change = 0;  // flow rate: final force, change over the last tau
  std::int64_t steps = 0;
  long nodes = 0;
};

double at_time(const core::NumericTable& table, const std::string& column, double t) {
  const auto time = table.column("time"), value = table.column(column);
  for (std::size_t k = 1; k < time.size(); ++k)
    if (time[k] >= t) {
      const double w = (t - time[k - 1]) / (time[k] - time[k - 1]);
      return (1 - w) * value[k - 1] + w * value[k];
    }
  throw std::runtime_error(fmt::format("poiseuille_pipe: the table ends before t = {} s", t));
}

void run_level(const Context& ctx, Level& level) {
  const double h = 2 * kRadius / level.n, mid = 1.5 * h;
  const auto dir = ctx.out_dir / "runs" /
                   fmt::format("{}_d{}", level.flow_rate ? "flow_rate" : "gradient", level.n);
  SceneRun measure;
  measure.at_end = [&](const run::Simulation& sim) {
    const auto& local = sim.local();
    double e2 = 0, volume = 0;
    for (int i = 0; i < local.num_owned; ++i) {
      const auto& x = local.position[i];
      const double r = std::min(std::hypot(x.x(), x.y()), kRadius);
      const double du = sim.state().velocity[i].z() - steady_velocity(r);
      e2 += local.volume[i] * du * du;
      volume += local.volume[i];
    }
    level.profile_error = std::sqrt(local.comm.sum(e2) / local.comm.sum(volume)) / kUmax;
    level.nodes = local.global_nodes;
  };
  std::vector<std::string> overrides = {
      fmt::format("mesh.periodic_pipe.size={:.17g}", h),
      fmt::format("mesh.periodic_pipe.length={:.17g}", 3 * h),
      fmt::format("probe.centre.position=[0.0, 0.0, {:.17g}]", mid),
      fmt::format("section.cut.point=[0.0, 0.0, {:.17g}]", mid)};
  if (level.flow_rate)
    overrides.push_back(fmt::format("section.other.point=[0.0, 0.0, {:.17g}]", 0.5 * h));
  const auto result = run_scene_file(
      case_scene("poiseuille_pipe",
                 level.flow_rate ? "poiseuille_pipe_flow_rate.toml" : "poiseuille_pipe.toml"),
      overrides, dir, ctx.comm, measure);
  level.steps = result.summary.steps;
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (rank != 0) return;
  const double tau = viscous_time();
  const auto wss =
      core::read_numeric_table(dir / "wall_shear_history.csv", core::TableHeader::required);
  const auto sections = core::read_numeric_table(dir / "sections.csv", core::TableHeader::required);
  level.flux = sections.column("cut_flux").back();
  // The time-averaged wall shear of every wall node (steady over the averaging window).
  // patch (a name), node, x, y, z, area, tawss, osi, rrt, tau_x, tau_y, tau_z, support_fraction:
  // the numbers read strictly.
  core::TableLines lines(dir / "wall_shear.csv", {});
  for (bool header = true; lines.next(); header = false) {
    const auto fields = lines.fields();
    if (header) continue;
    if (fields.size() != 13) throw lines.error(1, "expected 13 columns");
    const double tawss = lines.number(fields[6], "tawss");
    level.wss_nodal = std::max(level.wss_nodal, std::abs(tawss / (kForce * kRadius / 2) - 1));
  }
  if (!level.flow_rate) {
    level.wss_error = std::abs(wss.column("wall_mean_wss").back() / (kForce * kRadius / 2) - 1);
    const auto probes = core::read_numeric_table(dir / "probes.csv", core::TableHeader::required);
    for (double t : {0.5 * tau, tau, 2 * tau})
      level.startup_error = std::max(
          level.startup_error, std::abs(at_time(probes, "centre_w", t) - startup_axis(t)) / kUmax);
    return;
  }
  const auto time = sections.column("time"), cut = sections.column("cut_flux"),
             other = sections.column("other_flux");
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (!(time[k] > 0)) continue;  // the state at rest before the first step
    level.held = std::max(level.held, std::abs(cut[k] / kFlowRate - 1));
    if (time[k] >= tau)
      level.held_other = std::max(level.held_other, std::abs(other[k] / kFlowRate - 1));
  }
  const auto log = core::read_numeric_table(dir / "log.csv", core::TableHeader::required);
  const double end = log.column("time").back();
  level.force = log.column("force_z").back();
  level.force_change = std::abs(level.force - at_time(log, "force_z", end - tau)) / kForce;
  level.wss_error = std::abs(wss.column("wall_mean_wss").back() / (kForce * kRadius / 2) - 1);
}

void run_case(const Context& ctx, Report& report) {
  std::vector<Level> levels;
  for (int n : ctx.quick ? std::vector<int>{8, 16} : std::vector<int>{8, 16, 32})
    levels.push_back({n, false});
  levels.push_back({16, true});
  for (auto& l : levels) run_level(ctx, l);
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  for (auto& l : levels)  // measured on rank 0 from the files
    for (double* x : {&l.wss_error, &l.wss_nodal, &l.startup_error, &l.flux, &l.held, &l.held_other,
                      &l.force, &l.force_change})
      core::Comm(ctx.comm).broadcast(*x);
  if (rank == 0) {
    std::ofstream csv(ctx.out_dir / "levels.csv");
    csv << "drive,n,h,nodes,steps,profile_l2_over_umax,wss_mean_relative_error,"
           "wss_max_nodal_relative_error,startup_error_over_umax,flux,flow_rate_held,"
           "flow_rate_held_other,force,force_change\n";
    for (const auto& l : levels)
      csv << fmt::format(
          "{},{},{:.6g},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.12e},{:.3e},{:.3e},{:.12g},{:.3e}\n",
          l.flow_rate ? "flow_rate" : "gradient", l.n, 2 * kRadius / l.n, l.nodes, l.steps,
          l.profile_error, l.wss_error, l.wss_nodal, l.startup_error, l.flux, l.held, l.held_other,
          l.force, l.force_change);
  }
  const auto& control = levels.back();
  const auto& fine = levels[levels.size() - 2];
  const auto& coarse = levels[levels.size() - 3];
  const auto& same = *std::find_if(levels.begin(), levels.end(), [&](const Level& l) {
    return !l.flow_rate && l.n == control.n;
  });
  // Bounds: the measured errors (docs/validation.md) with margin; the orders of a 2nd-order
  // scheme on a triangulated disk whose polygonal wall is 2nd order too.
  report.add(fmt::format("gradient D/{}: steady profile L2 error / u_max", fine.n),
             fine.profile_error, 0, ctx.quick ? 1e-3 : 3e-4, Check::at_most);
  report.add(fmt::format("gradient D/{} -> D/{}: order of the profile error", coarse.n, fine.n),
             std::log2(coarse.profile_error / fine.profile_error), 2.0, 0.3, Check::at_least);
  // The mean wall shear is the steady momentum balance F V = tau A_wall: exact to round-off on
  // any mesh. The nodal values scatter with the wall spacing of the disk (reported).
  report.add(fmt::format("gradient D/{}: mean wall shear stress / (F R / 2) - 1", fine.n),
             fine.wss_error, 0, 1e-9, Check::at_most);
  report.add(
      fmt::format("gradient D/{}: max nodal |wall shear / (F R / 2) - 1| (reported)", fine.n),
      fine.wss_nodal, 0, 2e-2, Check::at_most);
  report.add(fmt::format("gradient D/{}: flux Q_h(F) / (pi R^2 u_max / 2) - 1", fine.n),
             fine.flux / kFlowRate - 1, 0, ctx.quick ? 1e-2 : 3e-3, Check::within);
  report.add(fmt::format("gradient D/{} -> D/{}: order of the flux error", coarse.n, fine.n),
             std::log2((coarse.flux / kFlowRate - 1) / (fine.flux / kFlowRate - 1)), 2.0, 0.3,
             Check::at_least);
  report.add(fmt::format("gradient D/{}: start-up at the axis vs Bessel series / u_max "
                         "(t = tau/2, tau, 2 tau)",
                         fine.n),
             fine.startup_error, 0, ctx.quick ? 6e-3 : 2e-3, Check::at_most);
  report.add(fmt::format("gradient D/{} -> D/{}: order of the start-up error", coarse.n, fine.n),
             std::log2(coarse.startup_error / fine.startup_error), 2.0, 0.3, Check::at_least);
  // The target: the flow rate held to 1e-6 after the transient. The correction makes
  // the controlled cut's flux the target to round-off at every step; the other cut carries the
  // same flux to the Poisson tolerance (every node's divergence is that small).
  report.add(fmt::format("flow rate D/{}: max |Q_cut / Q - 1| over all steps", control.n),
             control.held, 0, 1e-6, Check::at_most);
  report.add(fmt::format("flow rate D/{}: max |Q_other / Q - 1| after one viscous time", control.n),
             control.held_other, 0, 1e-6, Check::at_most);
  // Settled: the force's change over the last viscous time (e^-29 of the transient left).
  report.add(fmt::format("flow rate D/{}: force change over the last tau / F", control.n),
             control.force_change, 0, 1e-8, Check::at_most);
  // Linearity: the force that carries Q is F Q / Q_h(F) to the settling and Poisson errors.
  report.add(fmt::format("flow rate D/{}: force / (F Q / Q_h(F)) - 1 (the pressure-driven run)",
                         control.n),
             control.force * same.flux / (kForce * kFlowRate) - 1, 0, 1e-7, Check::within);
  report.add(fmt::format("flow rate D/{}: force / (8 mu Q / (pi R^4)) - 1", control.n),
             control.force / kForce - 1, 0, 1e-2, Check::within);
  // The exact profile and wall shear of Q: the pressure-driven level's discretisation errors.
  report.add(fmt::format("flow rate D/{}: steady profile L2 error / u_max", control.n),
             control.profile_error, 0, 6e-3, Check::at_most);
  report.add(fmt::format("flow rate D/{}: wall shear stress / (4 mu Q / (pi R^3)) - 1", control.n),
             control.wss_error, 0, 1e-2, Check::at_most);
}

}  // namespace

Case poiseuille_pipe_case() {
  return {"poiseuille_pipe",
          "Periodic pipe driven by a mean pressure gradient ([forcing] uniform) and by a flow "
          "rate ([forcing] flow_rate): profile, wall shear and their order, the start-up series, "
          "the flow rate held and the force it takes",
          run_case};
}

}  // namespace valsalva::validation
