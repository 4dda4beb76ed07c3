// Womersley flow in a rigid straight pipe (Womersley, J. Physiol. 127, 553-563, 1955; issue 3
// item 3 and issue 4 item 2): Wo = 17 (the reference experiment: blood analogue, 60 bpm,
// D = 24.5 mm) and Wo = 4, sine flow rate with the exact Womersley inlet profile, pressure
// outlet, at D/10 and D/20 (the target level). Set-up and sampling: womersley_run.hpp.
// Measured: max and L2 error of the axial velocity on the mid-length section at 8 phases of the
// 4th period, relative to the peak centreline velocity; target below 2 % max at D/20.
// The mesh: a Gmsh 2D disk triangulation extruded into prism layers of height h and split into
// tetrahedra (io/extruded_pipe_generator.hpp), with Gmsh BoundaryLayer rows along the wall at
// Wo 17 (first 0.2 h, ratio 1.2, to 1.5 h: wall_rows()); Gmsh's 3D Delaunay tetrahedra of the
// same size h are the comparison rows (and carry the LES and convective-outlet rows).
// Measured with build/bin/bench_womersley_study (same run_womersley; --extruded 1 --bl_first
// 0.2 --bl_ratio 1.2 --bl_thickness 1.5 and --npd / --wo as listed; --mesh_stats 1 for the
// mesh columns; "npd by edge" = D / median edge, "section npd" = the nodes per diameter of an
// equilateral triangulation with the mid section's node count):
//   mesh (Wo 17)                      nodes  npd by edge  section npd  D/10 max   D/20 max (L2)
//   Delaunay h                        11.5 k      15.5         -       15.2 %     5.33 % (2.51)
//   Delaunay 0.78 h (equal nodes)     22.8 k      19.7         -       10.05 %    4.74 % (1.68)
//   Delaunay wall-graded              43 k          -          -        7.8 %     3.13 % (0.75)
//   extruded, no rows                 17.0 k      20.0       21.4      10.55 %        -
//   extruded, rows 0.3 h x1.2 to 1 h  22.1 k      20.0       24.4       2.79 %    2.33 % (0.64)
//   extruded, rows 0.2 h x1.2 to 1.5h 29.8 k      20.0       28.3       1.90 %    0.65 % (0.32)
//   Wo 4, extruded, no rows           16.9 k      20.0       21.3       2.39 %    0.57 % (0.33)
// (node counts at D/20; the Delaunay rows are the earlier study's numbers, same solver.) So the
// target is met on the extruded pipe with the wall rows: Wo 17 0.65 % max, 0.32 % L2 (order
// 1.55 max, 1.46 L2 from D/10's 1.90 / 0.88 %); Wo 4 0.57 % (order 2.07). Honest count: at
// "D/20" the mid section holds 727 nodes at Wo 17 (the rows add 313 to the 414 of the plain
// disk), i.e. 28 nodes per diameter by node count, but the bulk spacing is h = D/20 and the
// Delaunay mesh of equal node count stays at 4.74 %: the rows, not the count, do it.
// Why: the error of the Delaunay mesh sits in the Stokes layer (delta = 0.83 h at D/20): the
// piecewise-linear field through nodes 0.8 - 1.0 h from the wall under-represents its flux, so
// the imposed Q(t) shifts the core (+2.7 %), and the wall-adjacent tetrahedra scatter by ~1 %.
// Rows at 0.2 - 1.5 h resolve the layer: the core offset drops to 0.4 %. Gmsh's BoundaryLayer
// rows are not deterministic (the same spec gives other nodes in another call, test_extruded_
// pipe), so rank 0 makes the disk for all ranks; two such D/20 meshes gave 0.65 % (study tool)
// and 0.67 % (this case), D/10 1.90 / 1.91 / 1.95 % (the last at np 2).
// `valsalva validate womersley` (np 1, shared machine, 1690 s): all checks pass; Wo 17 D/20
// 0.670 % max, 0.319 % L2; Wo 4 D/20 0.574 %, 0.332 %; orders D/10 -> D/20 1.51 (Wo 17), 2.06
// (Wo 4), L2 1.47; Delaunay D/20 5.33 %, D/10 15.14 %. `--quick` gives the same 0.0239185 at
// np 1 and np 2. With rows only to 1 h
// (two rows, the last at 0.66 h) the max, -2.3 %, sits on the last row (r = 0.934 R): the jump
// to the unstructured bulk there misses the profile's curvature just inside the layer. Plot of
// the error over r at the worst phase: validation/womersley/plot_study.py OUT.png with the
// runs' --csv files. At Wo 4 the Stokes layer is 3.5 h thick: no rows, and rows 0.3 h thick
// put the viscous RK4 limit below the run's dt (the run stops with "beyond the RK4 stability
// limit", measured). Layer height along z (Wo 17, D/10, rows): dz 0.5 h 1.70 % (11.6 k nodes)
// against 1.90 % at dz = h; dz = 2 h blew up at step 57 (t = 0.145 s; thin rows stretched to
// 2 h in z, not investigated), so dz = h. The max over the 8 phases is the worst phase; at D/20
// the phases spread 0.40 - 0.65 %. Not tried: D/30 (~100 k nodes with the rows, too costly here).
// Outlet: the pressure outlet is the exact condition (p is uniform over every section of the
// exact flow, du/dn = 0); with the do-nothing viscous flux and the whole backflow term
// (flow/boundary_conditions.hpp) it gives the same D/20 errors as a convective outlet on the
// Delaunay mesh (5.33 % vs 5.34 % max). The Delaunay runs that blew up at t = 0.85 - 0.89 s
// before the backflow fix now run: 0.78 h, L = 4 D: 10.28 % max; wall-graded D/10 (`--npd 10
// --size_factor 0.78 --wall_size 0.6 --wall_distance 1`, 6.4 k nodes): 9.24 % max, 3.25 % L2.
// Not levers (Delaunay, D/10, 0.78 h, 10.05 % max): dt (cfl 0.2: 10.56 %), the Poisson
// tolerance (1e-13: same digits), the P1 viscous weights (9.83 %), pipe length (L = 4 D with
// the convective outlet 9.86 %). The pressure damping is needed: without it 32 % max.
// The flux diagnostic of the study tool (Q against the mean flux of the run and of the exact
// nodal values over the middle third) divides by that third's dual volume / pi R^2.
// LES on the laminar flow: the sigma operator is zero for the pure shear du_z/dr, so nu_sgs
// vanishes on the exact (parallel) initial field; over the run it only sees the discrete
// transverse velocities, so here it is information (the 1e-8 check is made on the
// periodic pipe, validation/womersley_periodic). Smagorinsky's spurious nu_sgs is reported. Table:
// levels.csv; profiles.csv and curves.csv, plotted by plot.py into womersley_profiles.png.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "validation/case.hpp"
#include "validation/womersley/womersley_run.hpp"

namespace valsalva::validation {

namespace {

// Wall rows of the extruded disk (units of the mesh size h): first row 0.2 h from the wall,
// growing by 1.2 up to 1.5 h (5 rows at 0.2, 0.44, 0.73, 1.07, 1.49 h), so the Wo 17 Stokes
// layer (0.83 h at D/20) and the curved profile just inside it are resolved (header).
io::DiskWallGrading wall_rows() {
  io::DiskWallGrading g;
  g.layer_first = 0.2, g.layer_ratio = 1.2, g.layer_thickness = 1.5;
  return g;
}

struct Run {
  std::string label;
  WomersleySetup setup;
  WomersleyResult result;
  double change = 0;  // LES: max |u - u_laminar| / u_peak at the end (same mesh, partition)
};

// The laminar run on the same mesh, outlet and steps as `les`, among the runs before it.
const Run* laminar_twin(const std::vector<Run>& runs, const Run& les) {
  for (const auto& r : runs) {
    if (&r == &les) break;
    const auto &a = r.setup, &b = les.setup;
    if (a.les_model == "none" && a.womersley == b.womersley && a.extruded == b.extruded &&
        a.nodes_per_diameter == b.nodes_per_diameter && a.outlet == b.outlet &&
        a.sample_period == b.sample_period && a.cfl == b.cfl &&
        a.length_in_diameters == b.length_in_diameters)
      return &r;
  }
  return nullptr;
}

void write_profiles(const Context& ctx, const std::vector<Run>& runs) {
  std::ofstream p(ctx.out_dir / "profiles.csv"), c(ctx.out_dir / "curves.csv");
  p << "case,wo,npd,time,x,y,r,u,u_exact,u_peak,radius\n";
  c << "case,wo,time,s,u_exact,u_peak\n";
  for (const auto& run : runs) {
    const auto& r = run.result;
    const auto& exact = r.exact;
    for (const auto& s : r.phases) {
      for (std::size_t i = 0; i < s.r.size(); ++i)
        p << fmt::format("{},{},{},{:.6f},{:.6e},{:.6e},{:.6e},{:.9e},{:.9e},{:.9e},{:.9e}\n",
                         run.label, run.setup.womersley, run.setup.nodes_per_diameter, s.time,
                         s.x[i], s.y[i], s.r[i], s.u[i], s.exact[i], r.u_peak, r.radius);
      for (int k = 0; k <= 100; ++k) {
        const double sr = -1 + 2.0 * k / 100;
        c << fmt::format("{},{},{:.6f},{:.4f},{:.9e},{:.9e}\n", run.label, run.setup.womersley,
                         s.time, sr, exact.velocity(std::abs(sr) * r.radius, s.time), r.u_peak);
      }
    }
  }
}

void run_case(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const auto pressure = flow::BoundaryType::pressure_outlet;
  const auto convective = flow::BoundaryType::convective_outlet;
  // The case's mesh: the extruded disk with wall rows (see the header); delaunay = Gmsh's 3D
  // tetrahedra of the same size, the comparison rows.
  auto setup = [&](double wo, double npd, bool delaunay,
                   flow::BoundaryType outlet = flow::BoundaryType::pressure_outlet,
                   const std::string& les = "none") {
    WomersleySetup s;
    s.womersley = wo, s.nodes_per_diameter = npd, s.outlet = outlet, s.les_model = les;
    s.extruded = !delaunay;
    // Rows for the thin Stokes layer of Wo 17 only: at Wo 4 it is 3.5 h thick at D/20, and rows
    // 0.3 h thick would put the viscous RK4 limit below the case's dt (measured: the run stops).
    if (wo > 10) s.grading = wall_rows();
    return s;
  };
  const auto quick_setup = [&](const std::string& les) {
    auto s = setup(4, 10, false, pressure, les);
    s.sample_period = 0;  // the 1st period
    return s;
  };
  std::vector<Run> runs;
  if (ctx.quick)
    runs = {{"wo4_d10", quick_setup("none"), {}, 0},
            {"wo4_d10_sigma", quick_setup("sigma"), {}, 0},
            {"wo4_d10_smagorinsky", quick_setup("smagorinsky"), {}, 0}};
  else  // the cheap D/10 runs first: levels.csv is written as the runs finish
    runs = {{"wo17_d10", setup(17, 10, false), {}, 0},
            {"wo4_d10", setup(4, 10, false), {}, 0},
            {"wo17_d10_delaunay", setup(17, 10, true), {}, 0},
            {"wo17_d10_delaunay_convective_outlet", setup(17, 10, true, convective), {}, 0},
            {"wo17_d10_delaunay_sigma", setup(17, 10, true, pressure, "sigma"), {}, 0},
            {"wo17_d10_delaunay_smagorinsky", setup(17, 10, true, pressure, "smagorinsky"), {}, 0},
            {"wo17_d20", setup(17, 20, false), {}, 0},
            {"wo4_d20", setup(4, 20, false), {}, 0},
            {"wo17_d20_delaunay", setup(17, 20, true), {}, 0}};
  std::ofstream csv;
  if (rank == 0) {
    csv.open(ctx.out_dir / "levels.csv");
    csv << "case,wo,nodes_per_diameter,mesh,outlet,les,nodes,steps,dt,u_peak,max_error,l2_error,"
           "transverse,max_nu_sgs_over_nu,mean_nu_sgs_over_nu,first_stage_nu_sgs_over_nu,"
           "interior_nu_sgs_over_nu,velocity_change,max_divergence,wall_s\n";
  }
  for (auto& run : runs) {
    run.result = run_womersley(run.setup, ctx.comm);
    const auto& r = run.result;
    if (const Run* twin = laminar_twin(runs, run); twin && run.setup.les_model != "none") {
      for (std::size_t i = 0; i < r.final_velocity.size(); ++i)
        run.change =
            std::max(run.change, std::abs(r.final_velocity[i] - twin->result.final_velocity[i]));
      run.change /= twin->result.u_peak;
    }
    if (rank != 0) continue;
    const bool conv = run.setup.outlet == convective;
    csv << fmt::format(
        "{},{},{},{},{},{},{},{},{:.6e},{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
        "{:.6e},{:.3e},{:.1f}\n",
        run.label, run.setup.womersley, run.setup.nodes_per_diameter,
        run.setup.extruded ? "extruded" : "delaunay", conv ? "convective" : "pressure",
        run.setup.les_model, r.nodes, r.steps, r.dt, r.u_peak, r.max_error, r.l2_error,
        r.transverse, r.max_nu_ratio, r.mean_nu_ratio, r.first_stage_nu_ratio, r.interior_nu_ratio,
        run.change, r.max_divergence, r.wall);
    csv.flush();
    fmt::print(
        "womersley {}: {} nodes, {} steps dt {:.3e} s, max error {:.4f} L2 {:.4f} transverse "
        "{:.2e} of u_peak {:.4f} m/s, nu_sgs/nu max {:.3e} mean {:.3e} first stage {:.3e} "
        "interior {:.3e}, velocity change {:.3e}, {:.0f} s\n",
        run.label, r.nodes, r.steps, r.dt, r.max_error, r.l2_error, r.transverse, r.u_peak,
        r.max_nu_ratio, r.mean_nu_ratio, r.first_stage_nu_ratio, r.interior_nu_ratio, run.change,
        r.wall);
  }
  if (rank == 0) write_profiles(ctx, runs);

  if (ctx.quick) {
    // Quick (2.6 k nodes, 3 x 472 steps, ~40 s): Wo 4 on the extruded D/10 pipe, 1st period.
    // Measured max error 0.024 (0.024 also over the 4th period); bound 0.035, which the
    // Delaunay mesh of the same size (0.044) and a wrong phase or amplitude of the inlet (O(1)
    // errors) fail.
    report.add("Wo 4, D/10: max axial error / u_peak (1st period)", runs[0].result.max_error, 0.0,
               0.035, Check::at_most);
    // The exact parallel field has a rank-1 velocity gradient: sigma3 = 0 up to the SVD's
    // round-off (1e-16 relative); a model that does not vanish in pure shear gives Smagorinsky's
    // ~0.15 here.
    report.add("Wo 4, D/10, sigma: max nu_sgs / nu on the exact initial field",
               runs[1].result.first_stage_nu_ratio, 0.0, 1e-12, Check::at_most);
    // Over the run sigma sees the discrete transverse velocities (0.5 % of u_peak): measured
    // max nu_sgs/nu 7.8e-2 at the ends, 3.1e-3 in the middle third over 4 periods; bound 1e-2
    // in the middle third, 30x below Smagorinsky's 0.32 there.
    report.add("Wo 4, D/10, sigma: max nu_sgs / nu in the middle third",
               runs[1].result.interior_nu_ratio, 0.0, 1e-2, Check::at_most);
    report.add("Wo 4, D/10, smagorinsky: max nu_sgs / nu in the middle third (> sigma's)",
               runs[2].result.interior_nu_ratio, 1e-2, 0.0, Check::at_least);
    return;
  }
  const auto find = [&](const std::string& label) -> const Run& {
    return *std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.label == label; });
  };
  const auto& wo17 = find("wo17_d20").result;
  const auto& wo4 = find("wo4_d20").result;
  // The target: 2 % of the peak centreline velocity at D/20, max and L2.
  report.add("Wo 17, D/20: max axial error / u_peak (4th period, 8 phases)", wo17.max_error, 0.0,
             0.02, Check::at_most);
  report.add("Wo 4, D/20: max axial error / u_peak (4th period, 8 phases)", wo4.max_error, 0.0,
             0.02, Check::at_most);
  report.add("Wo 17, D/20: L2 axial error / u_peak", wo17.l2_error, 0.0, 0.02, Check::at_most);
  report.add("Wo 4, D/20: L2 axial error / u_peak", wo4.l2_error, 0.0, 0.02, Check::at_most);
  // Convergence D/10 -> D/20: a second-order scheme gives 2; at least 1.
  const auto order = [](const WomersleyResult& coarse, const WomersleyResult& fine,
                        double ratio = 2.0, bool l2 = false) {
    return l2 ? std::log(coarse.l2_error / fine.l2_error) / std::log(ratio)
              : std::log(coarse.max_error / fine.max_error) / std::log(ratio);
  };
  report.add("Wo 17: observed order of the max error, D/10 -> D/20",
             order(find("wo17_d10").result, wo17), 2.0, 1.0, Check::at_least);
  report.add("Wo 4: observed order of the max error, D/10 -> D/20",
             order(find("wo4_d10").result, wo4), 2.0, 1.0, Check::at_least);
  // The L2 error converges faster than the max, which sits in the Stokes layer r > 0.9 R.
  report.add("Wo 17: observed order of the L2 error, D/10 -> D/20",
             order(find("wo17_d10").result, wo17, 2.0, true), 2.0, 1.0, Check::at_least);
  // Gmsh's 3D Delaunay tetrahedra of the same size, reported (header: 5.33 % max at D/20, 15.2 %
  // at D/10); the bounds only catch a broken run.
  report.add("Wo 17, D/20, Delaunay tetrahedra: max axial error / u_peak (reported)",
             find("wo17_d20_delaunay").result.max_error, 0.0, 0.1, Check::at_most);
  report.add("Wo 17, D/10, Delaunay tetrahedra: max axial error / u_peak (reported)",
             find("wo17_d10_delaunay").result.max_error, 0.0, 0.3, Check::at_most);
  // Sigma on the inlet-driven pipe, as information: the 1e-8 targets are checked on the
  // periodic pipe (validation/womersley_periodic), where the discrete flow stays parallel. Here
  // the discrete flow is not parallel (transverse velocity 5 % of u_peak at D/10) and sigma
  // responds to that, i.e. these numbers measure the flow solver's transverse error: measured max
  // nu_sgs / nu 1.34, velocity change 2 % of u_peak. Bounds: below Smagorinsky's (max 5.8,
  // change 0.09-0.10), which also sees the shear itself.
  const auto& sigma = find("wo17_d10_delaunay_sigma");
  const auto& smag = find("wo17_d10_delaunay_smagorinsky");
  report.add("Wo 17, D/10 Delaunay, sigma: max nu_sgs / nu on the exact initial field",
             sigma.result.first_stage_nu_ratio, 0.0, 1e-12, Check::at_most);
  report.add(
      "Wo 17, D/10 Delaunay, sigma: max nu_sgs / nu over 4 periods (reported; <= Smagorinsky's)",
      sigma.result.max_nu_ratio, 0.0, smag.result.max_nu_ratio, Check::at_most);
  report.add(
      "Wo 17, D/10 Delaunay, sigma: max |u - u_laminar| / u_peak (reported; <= Smagorinsky's)",
      sigma.change, 0.0, smag.change, Check::at_most);
  // Reported, with bounds that only catch a broken model: Smagorinsky's nu_sgs of the shear
  // (C_s Delta)^2 |du/dr| is O(1) nu at D/10 (Delta ~ 1.5 mm, |du/dr| up to ~400 1/s; measured
  // max 5.8, mean 1.4), and it damps the Stokes layers: measured change 0.09-0.10 of u_peak
  // (pressure and convective outlets). The bound 0.25 catches a model on the wrong scale (a
  // Delta in mm gives 1e6 nu), not this known physical damping.
  report.add("Wo 17, D/10 Delaunay, smagorinsky: max nu_sgs / nu (reported)",
             smag.result.max_nu_ratio, 0.0, 20.0, Check::at_most);
  report.add("Wo 17, D/10 Delaunay, smagorinsky: mean nu_sgs / nu (reported)",
             smag.result.mean_nu_ratio, 0.0, 20.0, Check::at_most);
  report.add("Wo 17, D/10 Delaunay, smagorinsky: max |u - u_laminar| / u_peak (reported)",
             smag.change, 0.0, 0.25, Check::at_most);
  report.add("Wo 17, D/10 Delaunay, convective outlet: max axial error / u_peak (reported)",
             find("wo17_d10_delaunay_convective_outlet").result.max_error, 0.0, 0.3,
             Check::at_most);
}

}  // namespace

Case womersley_case() {
  return {"womersley",
          "Womersley pipe flow Wo 17 and 4 on tetrahedra: axial profiles at 8 phases vs exact, "
          "LES sigma/smagorinsky on the laminar flow",
          run_case};
}

}  // namespace valsalva::validation
