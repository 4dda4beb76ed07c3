// Verification 2 of issue 4 (the Sigma model on a laminar flow) on Womersley's own problem
// (Womersley, J. Physiol. 127, 553-563, 1955): validation/womersley_periodic/
// womersley_periodic.toml run by run::Simulation at each level, a streamwise-periodic pipe
// (mesh.source = "periodic_pipe": a triangulated disk extruded into identical prism layers, or
// the same prisms split into tetrahedra), Wo = 17, driven by the oscillating force density
// rho G(t) of the Womersley solution whose flow rate is Q(t) = Q0 (1 + sin(2 pi t / T))
// ([forcing] uniform, waveform sine) and started from that solution (initial.type = womersley).
// On this mesh the parallel flow u_z(x, y) e_z is a discrete solution: every operator of a
// z-invariant field on a z-invariant mesh gives z-invariant results, the convective and
// Laplacian terms have no transverse component, the divergence vanishes (the vertical dual faces
// of the horizontal edges carry no z flux, the two vertical edges cancel), so dp and the
// transverse velocity stay at round-off. The Sigma operator is zero for a velocity gradient of
// rank one (sigma2 = sigma3 = 0), so with sigma the run must repeat the laminar one: both within
// 1e-8 (issue 4, item 2). Split prisms (mesh/prism_split.hpp, the same diagonals in every layer)
// keep it too: each of a prism's three tetrahedra holds one vertical edge, so the linear
// interpolant of z-invariant nodal data has no z derivative, and the median-dual operators on
// tetrahedra are the P1 ones (Barth, VKI LS 1994-05); the split mesh also gets the consistent P1
// Poisson weights (on prisms the two-point weight, not consistent where S_jk is not parallel to
// the edge, but dp stays at round-off here).
// Measured against the exact solution (flow/womersley.hpp), by the case's observer after every
// step: the axial error over all nodes at 8 phases of the last period (max and L2 / u_peak), the
// transverse velocity over the whole run, nu_sgs / nu of the step's last RK stage with an LES
// model (les.update = "stage"), and at the end the change of the velocity against the laminar
// run on the same mesh and partition. dt: a convective CFL of 0.4 at the period's peak
// centreline velocity, rounded down to a whole number of steps per phase.
// Driven by the exact pressure gradient, the run carries no imposed flow rate: its flux misses
// Q(t) by the discretisation error while the core stays exact (numbers: docs/validation.md).
// Tables: levels.csv; samples.csv, plotted by plot.py into womersley_periodic.png.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <set>

#include "core/numeric_table.hpp"
#include "flow/womersley.hpp"
#include "run/simulation.hpp"
#include "validation/case.hpp"
#include "validation/gather_to_root.hpp"
#include "validation/nu_sgs_stats.hpp"
#include "validation/scene_run.hpp"
#include "validation/womersley_periodic/womersley_periodic_scene.hpp"

namespace valsalva::validation {

namespace {

constexpr double kDensity = 1100, kViscosity = 3.6e-3, kPeriod = 1.0;

struct Run : PeriodicLevel, PeriodicRun {
  std::string label;
  double change = 0;  // LES: max |u - u_laminar| / u_peak at the end (same mesh, partition)
  // Flow-rate drive: max |Q - Q(t)| / Q0 over the steps; max |F - rho G(t - dt/2)| / max |rho G|
  // over the last period (the force of a step acts over it: its midpoint).
  double held = 0, force_error = 0;
};

const Run& find(const std::vector<Run>& runs, const std::string& label) {
  const auto it =
      std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.label == label; });
  if (it == runs.end()) throw std::logic_error("womersley_periodic: no run " + label);
  return *it;
}

// The flow-rate drive's records: sections.csv and log.csv of the run (rank 0).
void read_drive(const std::filesystem::path& dir, const flow::Womersley& exact, Run& run) {
  const auto q = [&](double t) { return exact.mean * (1 + std::sin(2 * std::numbers::pi * t)); };
  const auto sections = core::read_numeric_table(dir / "sections.csv", core::TableHeader::required);
  const auto time = sections.column("time"), flux = sections.column("cut_flux");
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] > 0) run.held = std::max(run.held, std::abs(flux[k] - q(time[k])) / exact.mean);
  const auto log = core::read_numeric_table(dir / "log.csv", core::TableHeader::required);
  const auto t = log.column("time"), dt = log.column("dt"), force = log.column("force_z");
  double peak = 0;
  for (int k = 0; k < 1000; ++k)
    peak = std::max(peak, std::abs(kDensity * exact.pressure_gradient(kPeriod * k / 1000)));
  const double last = (run.periods - 1) * kPeriod;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > last + 1e-9)
      run.force_error = std::max(
          run.force_error,
          std::abs(force[k] - kDensity * exact.pressure_gradient(t[k] - dt[k] / 2)) / peak);
}

void run_one(const Context& ctx, Run& run, const flow::Womersley& exact) {
  const auto dir = ctx.out_dir / "runs" / run.label;
  static_cast<PeriodicRun&>(run) = run_periodic_level(run, exact, dir, ctx.comm);
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (run.flow_rate && rank == 0) read_drive(dir, exact, run);
  for (double* x : {&run.held, &run.force_error}) MPI_Bcast(x, 1, MPI_DOUBLE, 0, ctx.comm);
}

void write_samples(const Context& ctx, const std::vector<Run>& runs, double radius,
                   const flow::Womersley& exact) {
  std::ofstream out(ctx.out_dir / "samples.csv"), curves(ctx.out_dir / "curves.csv");
  out << "case,npd,time,r,u,u_exact,u_peak,radius\n";
  curves << "case,time,r,u_exact\n";
  for (const auto& run : runs) {
    if (run.les != "none" || run.split || run.flow_rate) continue;
    const auto& s = run.samples;
    for (std::size_t i = 0; i + 3 < s.size(); i += 4)
      out << fmt::format("{},{},{:.6f},{:.6e},{:.9e},{:.9e},{:.9e},{:.9e}\n", run.label, run.npd,
                         s[i], s[i + 1], s[i + 2], s[i + 3], run.u_peak, radius);
    std::set<double> times;
    for (std::size_t i = 0; i < s.size(); i += 4) times.insert(s[i]);
    for (const double t : times)
      for (int k = 0; k <= 100; ++k) {
        const double r = radius * k / 100;
        curves << fmt::format("{},{:.6f},{:.6e},{:.9e}\n", run.label, t, r, exact.velocity(r, t));
      }
  }
}

void run_case(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const int periods = ctx.quick ? 2 : 4;
  const auto exact = periodic_womersley_exact();
  std::vector<Run> runs;
  const auto add = [&](const std::string& label, double npd, bool split, const std::string& les) {
    Run r;
    r.label = label, r.npd = npd, r.split = split, r.les = les, r.periods = periods;
    runs.push_back(r);
  };
  add("prism_d10", 10, false, "none");
  add("prism_d10_sigma", 10, false, "sigma");
  add("prism_d10_smagorinsky", 10, false, "smagorinsky");
  add("tetra_d10", 10, true, "none");
  add("tetra_d10_sigma", 10, true, "sigma");
  add("prism_d10_flow_rate", 10, false, "none");
  runs.back().flow_rate = true;
  if (!ctx.quick) {
    add("prism_d20", 20, false, "none");
    add("prism_d20_sigma", 20, false, "sigma");
    add("prism_d20_wale", 20, false, "wale");
    add("prism_d20_smagorinsky", 20, false, "smagorinsky");
    add("tetra_d20", 20, true, "none");
    add("tetra_d20_sigma", 20, true, "sigma");
    add("prism_d40", 40, false, "none");
  }
  std::ofstream csv;
  if (rank == 0) {
    csv.open(ctx.out_dir / "levels.csv");
    csv << "case,nodes_per_diameter,cells,les,nodes,steps,dt,u_peak,max_error,l2_error,"
           "transverse,max_nu_sgs_over_nu,mean_nu_sgs_over_nu,velocity_change,max_divergence,"
           "wall_s,flow_rate_held,force_error\n";
  }
  for (auto& run : runs) {
    run_one(ctx, run, exact);
    if (run.les != "none") {
      const auto& twin = find(runs, run.label.substr(0, run.label.rfind('_')));
      for (std::size_t i = 0; i < run.final_velocity.size(); ++i)
        run.change = std::max(run.change, std::abs(run.final_velocity[i] - twin.final_velocity[i]));
      run.change /= twin.u_peak;
    }
    if (rank != 0) continue;
    csv << fmt::format(
        "{},{},{},{},{},{},{:.6e},{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
        "{:.6e},{:.3e},{:.1f},{:.3e},{:.6e}\n",
        run.label, run.npd, run.split ? "tetra" : "prism", run.les, run.nodes, run.steps, run.dt,
        run.u_peak, run.max_error, run.l2_error, run.transverse, run.max_nu_ratio,
        run.mean_nu_ratio, run.change, run.max_divergence, run.wall, run.held, run.force_error);
    csv.flush();
  }
  if (rank == 0) write_samples(ctx, runs, exact.radius, exact);
  const std::string level = ctx.quick ? "d10" : "d20";
  const auto& none = find(runs, "prism_" + level);
  const auto& sigma = find(runs, "prism_" + level + "_sigma");
  const auto& smag = find(runs, "prism_" + level + "_smagorinsky");
  const std::string where = fmt::format("Wo 17, prisms D/{}, {} periods", level.substr(1), periods);
  report.add(where + ": max |u_x, u_y| / u_peak without a model", none.transverse, 0.0, 1e-12,
             Check::at_most);
  report.add(where + ", sigma: max nu_sgs / nu over all steps", sigma.max_nu_ratio, 0.0, 1e-8,
             Check::at_most);
  report.add(where + ", sigma: max |u_sigma - u_none| / u_peak at the end", sigma.change, 0.0, 1e-8,
             Check::at_most);
  // Reported, with bounds that only catch a model on the wrong scale: Smagorinsky sees the
  // shear itself, O(1) nu at D/10, and damps the Stokes layers.
  report.add(where + ", smagorinsky: max nu_sgs / nu (reported)", smag.max_nu_ratio, 0.0, 20.0,
             Check::at_most);
  report.add(where + ", smagorinsky: mean nu_sgs / nu (reported)", smag.mean_nu_ratio, 0.0, 20.0,
             Check::at_most);
  report.add(where + ", smagorinsky: max |u_smag - u_none| / u_peak (reported)", smag.change, 0.0,
             0.25, Check::at_most);
  const auto& tetra = find(runs, "tetra_" + level + "_sigma");
  report.add(where + ", split tetrahedra: max |u_x, u_y| / u_peak without a model",
             find(runs, "tetra_" + level).transverse, 0.0, 1e-12, Check::at_most);
  report.add(where + ", split tetrahedra, sigma: max nu_sgs / nu", tetra.max_nu_ratio, 0.0, 1e-8,
             Check::at_most);
  report.add(where + ", split tetrahedra, sigma: max |u_sigma - u_none| / u_peak", tetra.change,
             0.0, 1e-8, Check::at_most);
  // The flow-rate drive of the same pipe: its target Q0 (1 + sin w t) held at every step, and the
  // force it takes against Womersley's rho G(t) (the discrete pipe carries a slightly different
  // flux for the same G, so the force differs by the discretisation error; reported).
  const auto& drive = find(runs, "prism_d10_flow_rate");
  const std::string at = fmt::format("Wo 17, prisms D/10, {} periods, flow-rate drive", periods);
  report.add(at + ": max |Q - Q(t)| / Q0 over all steps", drive.held, 0.0, 1e-6, Check::at_most);
  // D/10 does not resolve the Stokes layer (h = 0.2 R, thickness 0.083 R): the force that
  // carries Q(t) there has a larger amplitude than rho G; the bound catches a wrong drive (a
  // force of the wrong sign, scale or phase is O(1) off), not that discretisation error.
  report.add(at + ": max |F - rho G(t)| / max |rho G| over the last period (reported)",
             drive.force_error, 0.0, 0.15, Check::at_most);
  report.add(at + ": max axial error / u_peak (last period, reported)", drive.max_error, 0.0, 0.1,
             Check::at_most);
  if (ctx.quick) {
    // D/10 over 2 periods: bounds = the measured errors + 30 % (docs/validation.md). A wrong
    // drive (amplitude, phase, sign) gives O(0.1 - 1): Smagorinsky's damping alone is larger.
    report.add(where + ": max axial error / u_peak (last period, 8 phases)", none.max_error, 0.0,
               0.05, Check::at_most);
    report.add(where + ": L2 axial error / u_peak", none.l2_error, 0.0, 0.025, Check::at_most);
    return;
  }
  report.add(where + ", wale: max nu_sgs / nu (reported)",
             find(runs, "prism_d20_wale").max_nu_ratio, 0.0, 1e-8, Check::at_most);
  // Against the exact solution, 4th period. The max sits in the Stokes layer (thickness
  // sqrt(2 nu / w) = 0.083 R), which D/10 (h = 0.2 R) does not resolve: D/10 -> D/20 is
  // pre-asymptotic (reported); D/20 -> D/40 approaches the scheme's second order. Error bounds:
  // the D/40 max and the D/20 L2 below 1 %, half the issue-3 target of 2 % at D/20 for the
  // inlet-driven pipe.
  report.add("Wo 17, prisms D/20: max axial error / u_peak (reported)", none.max_error, 0.0, 0.03,
             Check::at_most);
  report.add("Wo 17, prisms D/20: L2 axial error / u_peak", none.l2_error, 0.0, 0.01,
             Check::at_most);
  report.add("Wo 17, prisms D/40: max axial error / u_peak", find(runs, "prism_d40").max_error, 0.0,
             0.01, Check::at_most);
  report.add("Wo 17, prisms D/40: L2 axial error / u_peak", find(runs, "prism_d40").l2_error, 0.0,
             0.01, Check::at_most);
  const auto order = [&](const std::string& a, const std::string& b, bool l2) {
    const auto &c = find(runs, a), &f = find(runs, b);
    return std::log(l2 ? c.l2_error / f.l2_error : c.max_error / f.max_error) / std::log(2.0);
  };
  report.add("Wo 17, prisms: observed order of the max error, D/10 -> D/20 (reported)",
             order("prism_d10", "prism_d20", false), 2.0, 1.5, Check::at_least);
  report.add("Wo 17, prisms: observed order of the L2 error, D/10 -> D/20 (reported)",
             order("prism_d10", "prism_d20", true), 2.0, 1.5, Check::at_least);
  report.add("Wo 17, prisms: observed order of the max error, D/20 -> D/40",
             order("prism_d20", "prism_d40", false), 2.0, 0.5, Check::at_least);
  report.add("Wo 17, prisms: observed order of the L2 error, D/20 -> D/40",
             order("prism_d20", "prism_d40", true), 2.0, 0.5, Check::at_least);
}

// The scene's overrides of a level: mesh, the exact start, the drive, the step and the model.
// The force rho G(t) is written as rho (G0 + A sin(w t + phase)) (G(t) - G0 = a cos w t +
// b sin w t, a = G(0) - G0, b = G(T/4) - G0: A = hypot(a, b), phase = atan2(a, b)).
std::vector<std::string> periodic_womersley_overrides(const PeriodicLevel& run,
                                                      const flow::Womersley& exact, double dt) {
  const double r = exact.radius, h = 2 * r / run.npd;
  const double q0 = exact.mean;
  std::vector<std::string> o = {
      fmt::format("mesh.periodic_pipe.radius={:.17g}", r),
      fmt::format("mesh.periodic_pipe.size={:.17g}", h),
      fmt::format("mesh.periodic_pipe.length={:.17g}", 3 * h),
      fmt::format("mesh.periodic_pipe.cells={}", run.split ? "tetra" : "prism"),
      fmt::format("initial.womersley.radius={:.17g}", r),
      fmt::format("initial.womersley.flow_rate={:.17g}", q0),
      fmt::format("initial.womersley.amplitude={:.17g}", q0),
      fmt::format("initial.womersley.period={:.17g}", kPeriod),
      fmt::format("forcing.period={:.17g}", kPeriod),
      fmt::format("time.dt={:.17g}", dt),
      fmt::format("time.end={:.17g}", run.periods * kPeriod),
      fmt::format("les.model={}", run.les)};
  if (run.flow_rate) {  // the target Q(t) = Q0 (1 + sin(w t)) through the mid-period section
    o.push_back(fmt::format("forcing.flow_rate={:.17g}", q0));
    o.push_back(fmt::format("forcing.flow_rate_amplitude={:.17g}", q0));
    o.push_back(fmt::format("section.cut.point=[0.0, 0.0, {:.17g}]", 1.5 * h));
    return o;
  }
  const double g0 = 0.5 * (exact.pressure_gradient(0) + exact.pressure_gradient(kPeriod / 2));
  const double a = exact.pressure_gradient(0) - g0, b = exact.pressure_gradient(kPeriod / 4) - g0;
  o.push_back(fmt::format("forcing.force=[0.0, 0.0, {:.17g}]", kDensity * g0));
  o.push_back(
      fmt::format("forcing.force_amplitude=[0.0, 0.0, {:.17g}]", kDensity * std::hypot(a, b)));
  o.push_back(fmt::format("forcing.phase={:.17g}", std::atan2(a, b)));
  return o;
}

}  // namespace

flow::Womersley periodic_womersley_exact(double womersley) {
  const double nu = kViscosity / kDensity, omega = 2 * std::numbers::pi / kPeriod;
  const double r = womersley * std::sqrt(nu / omega);
  const double q0 = 5 * 2 * r / kPeriod * std::numbers::pi * r * r;
  return flow::Womersley::from_sine(r, nu, q0, q0, kPeriod, 0.0);
}

PeriodicRun run_periodic_level(const PeriodicLevel& level, const flow::Womersley& exact,
                               const std::filesystem::path& run_dir, MPI_Comm comm) {
  const double t0 = MPI_Wtime();
  PeriodicRun run;
  const double r_pipe = exact.radius, h = 2 * r_pipe / level.npd, nu = kViscosity / kDensity;
  const double length = 3 * h;  // the period: 3 layers
  // The step: CFL level.cfl at the peak centreline velocity over the period, a whole number per
  // phase.
  for (int k = 0; k < 1000; ++k)
    run.u_peak = std::max(run.u_peak, exact.velocity(0.0, kPeriod * k / 1000));
  const double interval = kPeriod / level.phases;
  const auto per_phase =
      static_cast<std::int64_t>(std::ceil(interval / (level.cfl * h / run.u_peak)));
  run.dt = interval / per_phase;
  const std::int64_t first_sample = per_phase * level.phases * (level.periods - 1);
  double transverse = 0;
  NuSgsStats nu_sgs;
  std::vector<double> mine;
  auto radius_of = [&](const Eigen::Vector3d& x) {
    return std::min(std::hypot(x.x(), x.y()), r_pipe);
  };
  SceneRun measure;
  measure.observer = [&](const run::Simulation& sim, std::int64_t step) {
    const auto& local = sim.local();
    const auto& u = sim.state().velocity;
    for (int j = 0; j < local.num_owned; ++j)
      transverse = std::max(transverse, std::hypot(u[j].x(), u[j].y()));
    nu_sgs.add(local, sim.loop().subgrid_viscosity(), nu);
    if (step <= first_sample || (step - first_sample) % per_phase != 0) return;
    const double t = sim.state().time;
    double e2 = 0, volume = 0, emax = 0, q = 0, qe = 0;
    for (int j = 0; j < local.num_owned; ++j) {
      const double r = radius_of(local.position[j]), ue = exact.velocity(r, t);
      emax = std::max(emax, std::abs(u[j].z() - ue));
      e2 += local.volume[j] * (u[j].z() - ue) * (u[j].z() - ue);
      volume += local.volume[j];
      q += local.volume[j] * u[j].z(), qe += local.volume[j] * ue;
      mine.insert(mine.end(), {t, r, u[j].z(), ue});
    }
    run.max_error = std::max(run.max_error, local.comm.max(emax) / run.u_peak);
    run.l2_error =
        std::max(run.l2_error, std::sqrt(local.comm.sum(e2) / local.comm.sum(volume)) / run.u_peak);
    run.phase_time.push_back(t);
    run.mean_flux.push_back(local.comm.sum(q) / length);
    run.exact_mean_flux.push_back(local.comm.sum(qe) / length);
  };
  measure.at_end = [&](const run::Simulation& sim) {
    const auto& local = sim.local();
    run.nodes = local.global_nodes;
    run.transverse = local.comm.max(transverse) / run.u_peak;
    run.max_nu_ratio = nu_sgs.global_max(local);
    run.mean_nu_ratio = nu_sgs.global_mean(local);
    run.final_velocity =
        velocity_by_dual_node(local, sim.state().velocity, sim.metrics().num_nodes());
    run.samples = gather_to_root(mine, comm);
  };
  const auto result = run_scene_file(
      case_scene("womersley_periodic",
                 level.flow_rate ? "womersley_periodic_flow_rate.toml" : "womersley_periodic.toml"),
      periodic_womersley_overrides(level, exact, run.dt), run_dir, comm, measure);
  run.steps = result.summary.steps;
  run.max_divergence = result.summary.max_divergence;
  run.wall = MPI_Wtime() - t0;
  return run;
}

Case womersley_periodic_case() {
  return {"womersley_periodic",
          "Womersley's pressure-gradient driven periodic pipe (Wo 17) on extruded prisms: exact "
          "parallel flow, sigma vanishes (nu_sgs/nu, u_sigma - u_none below 1e-8), Smagorinsky "
          "reported, analytic error and order",
          run_case};
}

}  // namespace valsalva::validation
