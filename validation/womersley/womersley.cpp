// Womersley flow in a rigid straight pipe (Womersley, J. Physiol. 127, 553-563, 1955; issue 3
// item 3 and issue 4 item 2): Wo = 17 (the reference experiment: blood analogue, 60 bpm,
// D = 24.5 mm) and Wo = 4, sine flow rate with the exact Womersley inlet profile, pressure
// outlet, at D/10 and D/20 (the target level): validation/womersley/womersley.toml (and
// womersley_delaunay.toml) run by run::Simulation at each level, started from the exact
// solution. Measured by the case's observer after every step: the max and L2 error of the axial
// velocity over the nodes of the mid-length slab |z - L/2| <= h/2 at 8 phases of the sampled
// period (the 4th; quick: the 1st), relative to the peak centreline velocity (target below 2 %
// max at D/20); the transverse velocity there; with an LES model nu_sgs / nu of each step's last
// RK stage (les.update = "stage") over all nodes and over the middle third, and on the exact
// initial field (the model evaluated on the initial state before the first step, as the first
// stage does); at the end the change of the velocity against the laminar run on the same mesh.
// The mesh: a Gmsh 2D disk triangulation extruded into prism layers of height h and split into
// tetrahedra (mesh.source = "extruded_pipe", mesh/extruded_pipe_generator.hpp), with Gmsh
// BoundaryLayer rows along the wall at Wo 17 (first 0.2 h, ratio 1.2, to 1.5 h: they resolve the
// Stokes layer, 0.83 h thick at D/20, and the curved profile just inside it); Gmsh's 3D
// Delaunay tetrahedra of the same size h are the comparison rows (and carry the LES and
// convective-outlet rows). At Wo 4 the Stokes layer is 3.5 h thick: no rows (rows 0.3 h thick
// would put the viscous RK4 limit below the case's dt). Gmsh's BoundaryLayer rows are not
// deterministic, so rank 0 makes the disk for all ranks (build_mesh's communicator). The
// pressure outlet is the exact condition (p is uniform over every section of the exact flow).
// LES on the laminar flow: the sigma operator is zero for the pure shear du_z/dr, so nu_sgs
// vanishes on the exact (parallel) initial field; over the run it only sees the discrete
// transverse velocities, so here it is information (the 1e-8 check is made on the
// periodic pipe, validation/womersley_periodic). The mesh study behind these choices and every
// measured number: docs/validation.md (womersley). Tables: levels.csv; profiles.csv and
// curves.csv, plotted by plot.py into womersley_profiles.png.
#include "flow/womersley.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include "flow/operators.hpp"
#include "les/subgrid_viscosity.hpp"
#include "run/simulation.hpp"
#include "validation/case.hpp"
#include "validation/gather_to_root.hpp"
#include "validation/nu_sgs_stats.hpp"
#include "validation/scene_run.hpp"
#include "validation/womersley/womersley_scene.hpp"

namespace valsalva::validation {

namespace {

constexpr double kDensity = 1100, kViscosity = 3.6e-3, kPeriod = 1.0, kCfl = 0.4;
constexpr int kPhases = 8;

struct Setup {
  double wo = 17, npd = 20;  // Womersley number, mesh size D / npd
  bool delaunay = false;     // womersley_delaunay.toml instead of the extruded disk
  bool convective = false;   // a convective outlet instead of the pressure outlet
  std::string les = "none";
  int sample_period = 3;  // 0-based: 3 = the 4th period
};

struct Phase {
  double time = 0;
  std::vector<double> x, y, r, u, exact;  // slab nodes, gathered on rank 0
};

struct Run {
  std::string label;
  Setup setup;
  double radius = 0, length = 0, h = 0, u_peak = 0, dt = 0, wall = 0;
  long nodes = 0;
  std::int64_t steps = 0;
  double max_error = 0, l2_error = 0, transverse = 0, max_divergence = 0;
  double max_nu = 0, mean_nu = 0, first_nu = 0, interior_nu = 0;  // nu_sgs / nu
  double change = 0;  // LES: max |u - u_laminar| / u_peak at the end (same mesh, partition)
  std::vector<Phase> phases;
  std::vector<double> final_velocity;  // by dual node, every rank
};

// The laminar run on the same mesh, outlet and steps as `les`, among the runs before it.
const Run* laminar_twin(const std::vector<Run>& runs, const Run& les) {
  for (const auto& r : runs) {
    if (&r == &les) break;
    const auto &a = r.setup, &b = les.setup;
    if (a.les == "none" && a.wo == b.wo && a.delaunay == b.delaunay && a.npd == b.npd &&
        a.convective == b.convective && a.sample_period == b.sample_period)
      return &r;
  }
  return nullptr;
}

void run_one(const Context& ctx, Run& run) {
  const auto& s = run.setup;
  const double nu = kViscosity / kDensity;
  run.radius = womersley_radius(s.wo);
  const double d = 2 * run.radius;
  run.h = d / s.npd, run.length = 2 * d;
  const double q0 = 5 * d / kPeriod * std::numbers::pi * run.radius * run.radius;
  const auto exact = flow::Womersley::from_sine(run.radius, nu, q0, q0, kPeriod, 0.0);
  // The step: CFL kCfl at the peak centreline velocity over the period, a whole number per phase.
  for (int k = 0; k < 1000; ++k)
    run.u_peak = std::max(run.u_peak, exact.velocity(0.0, kPeriod * k / 1000));
  const double interval = kPeriod / kPhases;
  const auto per_phase =
      static_cast<std::int64_t>(std::ceil(interval / (kCfl * run.h / run.u_peak)));
  run.dt = interval / per_phase;
  const std::int64_t first_sample = per_phase * kPhases * s.sample_period;
  const double r_pipe = run.radius, l = run.length, h = run.h;
  auto radius_of = [&](const Eigen::Vector3d& x) {
    return std::min(std::hypot(x.x(), x.y()), r_pipe);
  };
  double transverse = 0, nu_interior = 0;
  NuSgsStats nu_stats;
  SceneRun measure;
  measure.at_start = [&](const run::Simulation& sim) {
    if (s.les == "none") return;
    // The model on the exact initial field, as the first RK stage evaluates it.
    const auto& local = sim.local();
    flow::TensorField g;
    flow::gradient(local, sim.state().velocity, g);
    flow::ScalarField nu_sgs(local.num_local(), 0.0);
    les::SubgridViscosity(les::parse_sgs_kind(s.les), std::nullopt, local.h)(g, nu_sgs);
    double worst = 0;
    for (int j = 0; j < local.num_owned; ++j) worst = std::max(worst, nu_sgs[j] / nu);
    run.first_nu = local.comm.max(worst);
  };
  measure.observer = [&](const run::Simulation& sim, std::int64_t step) {
    const auto& local = sim.local();
    const auto& u = sim.state().velocity;
    const auto& nu_sgs = sim.loop().subgrid_viscosity();
    nu_stats.add(local, nu_sgs, nu);
    for (int j = 0; j < (nu_sgs.empty() ? 0 : local.num_owned); ++j)
      if (std::abs(local.position[j].z() - l / 2) <= l / 6)
        nu_interior = std::max(nu_interior, nu_sgs[j] / nu);
    if (step <= first_sample || (step - first_sample) % per_phase != 0) return;
    Phase p;
    p.time = sim.state().time;
    double e2 = 0, volume = 0, emax = 0;
    std::vector<double> mine;
    for (int j = 0; j < local.num_owned; ++j) {
      const auto& x = local.position[j];
      if (std::abs(x.z() - l / 2) > h / 2) continue;  // the mid-length slab
      const double r = radius_of(x), ue = exact.velocity(r, p.time);
      emax = std::max(emax, std::abs(u[j].z() - ue));
      transverse = std::max(transverse, std::hypot(u[j].x(), u[j].y()));
      e2 += local.volume[j] * (u[j].z() - ue) * (u[j].z() - ue);
      volume += local.volume[j];
      mine.insert(mine.end(), {x.x(), x.y(), r, u[j].z(), ue});
    }
    run.max_error = std::max(run.max_error, local.comm.max(emax) / run.u_peak);
    run.l2_error =
        std::max(run.l2_error, std::sqrt(local.comm.sum(e2) / local.comm.sum(volume)) / run.u_peak);
    const auto all = gather_to_root(mine, ctx.comm);
    for (std::size_t i = 0; i + 4 < all.size(); i += 5) {
      p.x.push_back(all[i]), p.y.push_back(all[i + 1]), p.r.push_back(all[i + 2]);
      p.u.push_back(all[i + 3]), p.exact.push_back(all[i + 4]);
    }
    run.phases.push_back(std::move(p));
  };
  measure.at_end = [&](const run::Simulation& sim) {
    const auto& local = sim.local();
    run.nodes = local.global_nodes;
    run.transverse = local.comm.max(transverse) / run.u_peak;
    run.max_nu = nu_stats.global_max(local);
    run.mean_nu = nu_stats.global_mean(local);
    run.interior_nu = local.comm.max(nu_interior);
    run.final_velocity =
        velocity_by_dual_node(local, sim.state().velocity, sim.metrics().num_nodes());
  };
  const double t0 = MPI_Wtime();
  WomersleyLevel level;
  level.womersley = s.wo, level.nodes_per_diameter = s.npd, level.extruded = !s.delaunay;
  level.outlet = s.convective ? "convective_outlet" : "pressure_outlet";
  level.les_model = s.les, level.sample_period = s.sample_period, level.dt = run.dt;
  if (!s.delaunay && s.wo > 10)  // rows for the thin Stokes layer of Wo 17 only (header)
    level.layer_first = 0.2, level.layer_thickness = 1.5;
  const auto result = run_scene_file(womersley_scene(level), womersley_overrides(level),
                                     ctx.out_dir / "runs" / run.label, ctx.comm, measure);
  run.steps = result.summary.steps;
  run.max_divergence = result.summary.max_divergence;
  run.wall = MPI_Wtime() - t0;
}

void write_profiles(const Context& ctx, const std::vector<Run>& runs) {
  std::ofstream p(ctx.out_dir / "profiles.csv"), c(ctx.out_dir / "curves.csv");
  p << "case,wo,npd,time,x,y,r,u,u_exact,u_peak,radius\n";
  c << "case,wo,time,s,u_exact,u_peak\n";
  const double nu = kViscosity / kDensity;
  for (const auto& run : runs) {
    const double d = 2 * run.radius;
    const double q0 = 5 * d / kPeriod * std::numbers::pi * run.radius * run.radius;
    const auto exact = flow::Womersley::from_sine(run.radius, nu, q0, q0, kPeriod, 0.0);
    for (const auto& s : run.phases) {
      for (std::size_t i = 0; i < s.r.size(); ++i)
        p << fmt::format("{},{},{},{:.6f},{:.6e},{:.6e},{:.6e},{:.9e},{:.9e},{:.9e},{:.9e}\n",
                         run.label, run.setup.wo, run.setup.npd, s.time, s.x[i], s.y[i], s.r[i],
                         s.u[i], s.exact[i], run.u_peak, run.radius);
      for (int k = 0; k <= 100; ++k) {
        const double sr = -1 + 2.0 * k / 100;
        c << fmt::format("{},{},{:.6f},{:.4f},{:.9e},{:.9e}\n", run.label, run.setup.wo, s.time, sr,
                         exact.velocity(std::abs(sr) * run.radius, s.time), run.u_peak);
      }
    }
  }
}

void run_case(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  auto setup = [](double wo, double npd, bool delaunay, bool convective = false,
                  const std::string& les = "none") {
    Setup s;
    s.wo = wo, s.npd = npd, s.delaunay = delaunay, s.convective = convective, s.les = les;
    return s;
  };
  const auto quick_setup = [&](const std::string& les) {
    auto s = setup(4, 10, false, false, les);
    s.sample_period = 0;  // the 1st period
    return s;
  };
  std::vector<Run> runs;
  const auto add = [&](const std::string& label, const Setup& s) {
    Run r;
    r.label = label, r.setup = s;
    runs.push_back(r);
  };
  if (ctx.quick) {
    add("wo4_d10", quick_setup("none"));
    add("wo4_d10_sigma", quick_setup("sigma"));
    add("wo4_d10_smagorinsky", quick_setup("smagorinsky"));
  } else {  // the cheap D/10 runs first: levels.csv is written as the runs finish
    add("wo17_d10", setup(17, 10, false));
    add("wo4_d10", setup(4, 10, false));
    add("wo17_d10_delaunay", setup(17, 10, true));
    add("wo17_d10_delaunay_convective_outlet", setup(17, 10, true, true));
    add("wo17_d10_delaunay_sigma", setup(17, 10, true, false, "sigma"));
    add("wo17_d10_delaunay_smagorinsky", setup(17, 10, true, false, "smagorinsky"));
    add("wo17_d20", setup(17, 20, false));
    add("wo4_d20", setup(4, 20, false));
    add("wo17_d20_delaunay", setup(17, 20, true));
  }
  std::ofstream csv;
  if (rank == 0) {
    csv.open(ctx.out_dir / "levels.csv");
    csv << "case,wo,nodes_per_diameter,mesh,outlet,les,nodes,steps,dt,u_peak,max_error,l2_error,"
           "transverse,max_nu_sgs_over_nu,mean_nu_sgs_over_nu,first_stage_nu_sgs_over_nu,"
           "interior_nu_sgs_over_nu,velocity_change,max_divergence,wall_s\n";
  }
  for (auto& run : runs) {
    run_one(ctx, run);
    if (const Run* twin = laminar_twin(runs, run); twin && run.setup.les != "none") {
      for (std::size_t i = 0; i < run.final_velocity.size(); ++i)
        run.change =
            std::max(run.change, std::abs(run.final_velocity[i] - twin->final_velocity[i]));
      run.change /= twin->u_peak;
    }
    if (rank != 0) continue;
    const auto& s = run.setup;
    csv << fmt::format(
        "{},{},{},{},{},{},{},{},{:.6e},{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
        "{:.6e},{:.3e},{:.1f}\n",
        run.label, s.wo, s.npd, s.delaunay ? "delaunay" : "extruded",
        s.convective ? "convective" : "pressure", s.les, run.nodes, run.steps, run.dt, run.u_peak,
        run.max_error, run.l2_error, run.transverse, run.max_nu, run.mean_nu, run.first_nu,
        run.interior_nu, run.change, run.max_divergence, run.wall);
    csv.flush();
  }
  if (rank == 0) write_profiles(ctx, runs);

  if (ctx.quick) {
    // Quick: Wo 4 on the extruded D/10 pipe, 1st period. The bound (the measured error with
    // margin, docs/validation.md) fails on the Delaunay mesh of the same size and for a wrong
    // phase or amplitude of the inlet (O(1) errors).
    report.add("Wo 4, D/10: max axial error / u_peak (1st period)", runs[0].max_error, 0.0, 0.035,
               Check::at_most);
    // The exact parallel field has a rank-1 velocity gradient: sigma3 = 0 up to the SVD's
    // round-off (1e-16 relative); a model that does not vanish in pure shear (Smagorinsky) is
    // O(0.1) here.
    report.add("Wo 4, D/10, sigma: max nu_sgs / nu on the exact initial field", runs[1].first_nu,
               0.0, 1e-12, Check::at_most);
    // Over the run sigma sees the discrete transverse velocities; bound 1e-2 in the middle
    // third, far below Smagorinsky's there.
    report.add("Wo 4, D/10, sigma: max nu_sgs / nu in the middle third", runs[1].interior_nu, 0.0,
               1e-2, Check::at_most);
    report.add("Wo 4, D/10, smagorinsky: max nu_sgs / nu in the middle third (> sigma's)",
               runs[2].interior_nu, 1e-2, 0.0, Check::at_least);
    return;
  }
  const auto find = [&](const std::string& label) -> const Run& {
    return *std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.label == label; });
  };
  const auto& wo17 = find("wo17_d20");
  const auto& wo4 = find("wo4_d20");
  // The target: 2 % of the peak centreline velocity at D/20, max and L2.
  report.add("Wo 17, D/20: max axial error / u_peak (4th period, 8 phases)", wo17.max_error, 0.0,
             0.02, Check::at_most);
  report.add("Wo 4, D/20: max axial error / u_peak (4th period, 8 phases)", wo4.max_error, 0.0,
             0.02, Check::at_most);
  report.add("Wo 17, D/20: L2 axial error / u_peak", wo17.l2_error, 0.0, 0.02, Check::at_most);
  report.add("Wo 4, D/20: L2 axial error / u_peak", wo4.l2_error, 0.0, 0.02, Check::at_most);
  // Convergence D/10 -> D/20: a second-order scheme gives 2; at least 1.
  const auto order = [](const Run& coarse, const Run& fine, bool l2 = false) {
    return l2 ? std::log2(coarse.l2_error / fine.l2_error)
              : std::log2(coarse.max_error / fine.max_error);
  };
  report.add("Wo 17: observed order of the max error, D/10 -> D/20", order(find("wo17_d10"), wo17),
             2.0, 1.0, Check::at_least);
  report.add("Wo 4: observed order of the max error, D/10 -> D/20", order(find("wo4_d10"), wo4),
             2.0, 1.0, Check::at_least);
  // The L2 error converges faster than the max, which sits in the Stokes layer r > 0.9 R.
  report.add("Wo 17: observed order of the L2 error, D/10 -> D/20",
             order(find("wo17_d10"), wo17, true), 2.0, 1.0, Check::at_least);
  // Gmsh's 3D Delaunay tetrahedra of the same size, reported; the bounds only catch a broken run.
  report.add("Wo 17, D/20, Delaunay tetrahedra: max axial error / u_peak (reported)",
             find("wo17_d20_delaunay").max_error, 0.0, 0.1, Check::at_most);
  report.add("Wo 17, D/10, Delaunay tetrahedra: max axial error / u_peak (reported)",
             find("wo17_d10_delaunay").max_error, 0.0, 0.3, Check::at_most);
  // Sigma on the inlet-driven pipe, as information: the 1e-8 targets are checked on the
  // periodic pipe (validation/womersley_periodic), where the discrete flow stays parallel. Here
  // the discrete flow is not parallel and sigma responds to that, i.e. these numbers measure the
  // flow solver's transverse error. Bounds: below Smagorinsky's, which also sees the shear.
  const auto& sigma = find("wo17_d10_delaunay_sigma");
  const auto& smag = find("wo17_d10_delaunay_smagorinsky");
  report.add("Wo 17, D/10 Delaunay, sigma: max nu_sgs / nu on the exact initial field",
             sigma.first_nu, 0.0, 1e-12, Check::at_most);
  report.add(
      "Wo 17, D/10 Delaunay, sigma: max nu_sgs / nu over 4 periods (reported; <= Smagorinsky's)",
      sigma.max_nu, 0.0, smag.max_nu, Check::at_most);
  report.add(
      "Wo 17, D/10 Delaunay, sigma: max |u - u_laminar| / u_peak (reported; <= Smagorinsky's)",
      sigma.change, 0.0, smag.change, Check::at_most);
  // Reported, with bounds that only catch a broken model: Smagorinsky's nu_sgs of the shear
  // (C_s Delta)^2 |du/dr| is O(1) nu at D/10 and damps the Stokes layers; the bound 0.25 catches
  // a model on the wrong scale (a Delta in mm gives 1e6 nu), not this known physical damping.
  report.add("Wo 17, D/10 Delaunay, smagorinsky: max nu_sgs / nu (reported)", smag.max_nu, 0.0,
             20.0, Check::at_most);
  report.add("Wo 17, D/10 Delaunay, smagorinsky: mean nu_sgs / nu (reported)", smag.mean_nu, 0.0,
             20.0, Check::at_most);
  report.add("Wo 17, D/10 Delaunay, smagorinsky: max |u - u_laminar| / u_peak (reported)",
             smag.change, 0.0, 0.25, Check::at_most);
  report.add("Wo 17, D/10 Delaunay, convective outlet: max axial error / u_peak (reported)",
             find("wo17_d10_delaunay_convective_outlet").max_error, 0.0, 0.3, Check::at_most);
}

}  // namespace

double womersley_radius(double wo) {
  return wo * std::sqrt(kViscosity / kDensity / (2 * std::numbers::pi / kPeriod));
}

std::filesystem::path womersley_scene(const WomersleyLevel& level) {
  return case_scene("womersley", level.extruded ? "womersley.toml" : "womersley_delaunay.toml");
}

std::vector<std::string> womersley_overrides(const WomersleyLevel& s) {
  const double r = womersley_radius(s.womersley), d = 2 * r, l = s.length_in_diameters * d;
  const double size = s.mesh_size_factor * d / s.nodes_per_diameter;
  const double q0 = 5 * d / kPeriod * std::numbers::pi * r * r;
  const std::string mesh = s.extruded ? "mesh.extruded_pipe." : "mesh.pipe.";
  std::vector<std::string> o = {
      fmt::format("{}radius={:.17g}", mesh, r),
      fmt::format("{}length={:.17g}", mesh, l),
      fmt::format("{}size={:.17g}", mesh, size),
      fmt::format("initial.womersley.radius={:.17g}", r),
      fmt::format("initial.womersley.flow_rate={:.17g}", q0),
      fmt::format("initial.womersley.amplitude={:.17g}", q0),
      fmt::format("initial.womersley.period={:.17g}", kPeriod),
      fmt::format("initial.womersley.point=[0.0, 0.0, {:.17g}]", l),
      fmt::format("boundary.inlet.flow_rate={:.17g}", q0),
      fmt::format("boundary.inlet.amplitude={:.17g}", q0),
      fmt::format("boundary.inlet.period={:.17g}", kPeriod),
      fmt::format("boundary.outlet.type={}", s.outlet),
      fmt::format("les.model={}", s.les_model),
      fmt::format("flow.viscous_weights={}", s.stiffness_viscous ? "stiffness" : "two_point"),
      fmt::format("poisson.tolerance={:.17g}", s.poisson_tolerance),
      fmt::format("time.dt={:.17g}", s.dt),
      fmt::format("time.end={:.17g}", (s.sample_period + 1) * kPeriod),
      fmt::format("time.max_steps={}", s.max_steps)};
  if (!s.extruded) return o;
  const std::pair<const char*, double> graded[] = {{"layer_height", s.layer_height},
                                                   {"wall_size", s.wall_size},
                                                   {"wall_distance", s.wall_distance},
                                                   {"layer_first", s.layer_first},
                                                   {"layer_thickness", s.layer_thickness}};
  for (const auto& [key, value] : graded)
    o.push_back(fmt::format("{}{}={:.17g}", mesh, key, value * size));
  o.push_back(fmt::format("{}layer_ratio={:.17g}", mesh, s.layer_ratio));
  return o;
}

Case womersley_case() {
  return {"womersley",
          "Womersley pipe flow Wo 17 and 4 on tetrahedra: axial profiles at 8 phases vs exact, "
          "LES sigma/smagorinsky on the laminar flow",
          run_case};
}

}  // namespace valsalva::validation
