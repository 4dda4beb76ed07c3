// Womersley flow in a rigid straight pipe (Womersley, J. Physiol. 127, 553-563, 1955; issue 3
// item 3 and issue 4 item 2): tetrahedral pipe meshes at D/10, D/20 (the target level) and D/30
// (Wo 17 only; ~40 k nodes, the costliest run), Wo = 17
// (the reference experiment: blood analogue, 60 bpm, D = 24.5 mm) and Wo = 4, sine flow rate with
// the exact Womersley inlet profile, pressure outlet. Set-up and sampling: womersley_run.hpp.
// Measured: max and L2 error of the axial velocity on the mid-length section at 8 phases of the
// 4th period, relative to the peak centreline velocity.
// Outlet by measurement: the pressure outlet is the exact condition (p is uniform over every
// section of the exact flow, du/dn = 0); with the do-nothing viscous flux and the backflow
// stabilisation (flow/boundary_conditions.hpp) it runs at D/20, where before those it blew up at
// t = 0.92 s, and gives the same D/20 errors as a convective outlet (Wo 17: 5.33 % vs 5.34 %
// max, 2.51 % L2 both); the convective outlet at D/10 is a reported comparison.
// Why D/20 gives 5.33 % here and 2.07 % on the periodic prism pipe (validation/womersley_
// periodic), measured with validation/bench/womersley_study.cpp (Wo 17; plot_study.py draws the
// error over r at the worst phase, t = 3.125 s; the analytic reference was checked against
// scipy's Bessel functions and its flux against Q(t) to 2e-16):
// 1. Gmsh's Delaunay tetrahedra are coarser than the size asked for: median edge 1.29 h at D/20
//    (1.23 h at D/10), 0.91 nodes per h^3 against 1.76 for the extruded disk of the periodic
//    pipe (median edge 1.00 h), so this "D/20" is about D/15.5 by edge length. Asking Gmsh for
//    0.78 h gives median edge 1.02 h (22.8 k nodes instead of 11.5 k): 5.33 -> 4.74 % max,
//    2.51 -> 1.68 % L2 (D/10: 15.2 -> 10.1 % max, 7.4 -> 4.7 % L2).
// 2. The flow rate is imposed. The run's discrete flux (sum V_j u_z over the middle third) is
//    Q(t) to 0.1 %, but that of the exact nodal values misses Q by up to 1.6 % (0.9 % with the
//    0.78 h mesh, 4.7 % at D/10) of pi R^2 u_peak: the piecewise-linear field under-represents
//    the flux of a Stokes layer (delta = 0.83 h) whose first interior nodes sit at 0.8 - 1.0 h
//    from the wall. So the core sits 2.7 % (1.7 %) of u_peak off the exact value, in phase with
//    that deficit; the inlet's flux scaling raises the exact profile there by 1.6 % likewise.
//    The periodic pipe is driven by the exact pressure gradient and carries no imposed Q (its
//    flux misses Q by up to 1.1 % at D/20), so its core is exact; driven at Q(t) instead
//    (PeriodicSetup::flux_driven) it has a 1.3 % core offset and 1.48 % max, 1.07 % L2.
// 3. The rest sits at the wall-adjacent nodes, r ~ 0.9 R: -2 to -4.7 % with a node-to-node
//    scatter of ~1 % of u_peak on the tetrahedra, against -1 to -2 % on the disk's first row.
// Wall-graded (wall size 0.39 h growing to the bulk 0.78 h over 0.78 h, PipeMeshOptions; 43 k
// nodes): 3.13 % max, 0.75 % L2, the core offset 0.9 %, the max now the scatter of the
// wall-adjacent tetrahedra (D/10: 7.8 % max, 2.7 % L2). So below 2 % max at D/20 was not reached
// by these meshes; the case keeps Gmsh's size h. Not levers at D/10 (0.78 h mesh, 10.05 % max):
// dt (cfl 0.2: 10.56 %), the Poisson tolerance (1e-13: same digits), the P1 viscous weights
// (9.83 %), the outlet and pipe length (convective outlet, L = 4 D: 9.86 % vs 10.46 % at 2 D; the
// core offset reaches its plateau within D/2 of the inlet). The pressure damping is needed:
// without it 32 % max, transverse 14 % of u_peak. The pressure outlet blew up at t = 0.85 -
// 0.89 s (flow reversal) on two D/10 meshes (0.78 h with L = 4 D, where the convective outlet
// ran; graded 0.47 h at the wall). With the whole backflow term since (flow/boundary_conditions
// .hpp) the first runs its 4 periods (10.28 % max); the graded one was not re-run.
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
    if (a.les_model == "none" && a.womersley == b.womersley &&
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
  auto setup = [](double wo, double npd, flow::BoundaryType outlet, const std::string& les) {
    WomersleySetup s;
    s.womersley = wo, s.nodes_per_diameter = npd, s.outlet = outlet, s.les_model = les;
    return s;
  };
  const auto pressure = flow::BoundaryType::pressure_outlet;
  const auto convective = flow::BoundaryType::convective_outlet;
  const auto quick_setup = [&](const std::string& les) {
    auto s = setup(4, 10, pressure, les);
    s.sample_period = 0;  // the 1st period
    return s;
  };
  std::vector<Run> runs;
  if (ctx.quick)
    runs = {{"wo4_d10", quick_setup("none"), {}, 0},
            {"wo4_d10_sigma", quick_setup("sigma"), {}, 0},
            {"wo4_d10_smagorinsky", quick_setup("smagorinsky"), {}, 0}};
  else  // the cheap D/10 runs first: levels.csv is written as the runs finish
    runs = {{"wo17_d10", setup(17, 10, pressure, "none"), {}, 0},
            {"wo4_d10", setup(4, 10, pressure, "none"), {}, 0},
            {"wo17_d10_convective_outlet", setup(17, 10, convective, "none"), {}, 0},
            {"wo17_d10_sigma", setup(17, 10, pressure, "sigma"), {}, 0},
            {"wo17_d10_smagorinsky", setup(17, 10, pressure, "smagorinsky"), {}, 0},
            {"wo17_d20", setup(17, 20, pressure, "none"), {}, 0},
            {"wo4_d20", setup(4, 20, pressure, "none"), {}, 0},
            {"wo17_d30", setup(17, 30, pressure, "none"), {}, 0}};
  std::ofstream csv;
  if (rank == 0) {
    csv.open(ctx.out_dir / "levels.csv");
    csv << "case,wo,nodes_per_diameter,outlet,les,nodes,steps,dt,u_peak,max_error,l2_error,"
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
        "{},{},{},{},{},{},{},{:.6e},{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
        "{:.6e},{:.3e},{:.1f}\n",
        run.label, run.setup.womersley, run.setup.nodes_per_diameter,
        conv ? "convective" : "pressure", run.setup.les_model, r.nodes, r.steps, r.dt, r.u_peak,
        r.max_error, r.l2_error, r.transverse, r.max_nu_ratio, r.mean_nu_ratio,
        r.first_stage_nu_ratio, r.interior_nu_ratio, run.change, r.max_divergence, r.wall);
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
    // Quick (1.8 k nodes, 3 x 472 steps, ~15 s): Wo 4 on D/10, 1st period. Measured max error
    // 0.044 (0.044 also over the 4th period); bound 0.06 = 4 x the 1.5 % D/20 target of a
    // second-order scheme, which a wrong phase or amplitude of the inlet (O(1) errors) fails.
    report.add("Wo 4, D/10: max axial error / u_peak (1st period)", runs[0].result.max_error, 0.0,
               0.06, Check::at_most);
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
  report.add("Wo 17: observed order of the max error, D/20 -> D/30",
             order(wo17, find("wo17_d30").result, 1.5), 2.0, 1.0, Check::at_least);
  // The L2 error converges faster than the max, which sits in the Stokes layer r > 0.9 R
  // (thickness sqrt(2 nu / w) = 0.083 R, about one cell at D/20 and D/30).
  report.add("Wo 17: observed order of the L2 error, D/10 -> D/20",
             order(find("wo17_d10").result, wo17, 2.0, true), 2.0, 1.0, Check::at_least);
  report.add("Wo 17: observed order of the L2 error, D/20 -> D/30",
             order(wo17, find("wo17_d30").result, 1.5, true), 2.0, 1.0, Check::at_least);
  report.add("Wo 17, D/30: L2 axial error / u_peak (reported)", find("wo17_d30").result.l2_error,
             0.0, 0.02, Check::at_most);
  report.add("Wo 17, D/30: max axial error / u_peak (reported)", find("wo17_d30").result.max_error,
             0.0, 0.02, Check::at_most);
  // Sigma on the inlet-driven pipe, as information: the 1e-8 targets are checked on the
  // periodic pipe (validation/womersley_periodic), where the discrete flow stays parallel. Here
  // the discrete flow is not parallel (transverse velocity 5 % of u_peak at D/10) and sigma
  // responds to that, i.e. these numbers measure the flow solver's transverse error: measured max
  // nu_sgs / nu 1.34, velocity change 2 % of u_peak. Bounds: below Smagorinsky's (max 5.8,
  // change 0.09-0.10), which also sees the shear itself.
  const auto& sigma = find("wo17_d10_sigma");
  const auto& smag = find("wo17_d10_smagorinsky");
  report.add("Wo 17, D/10, sigma: max nu_sgs / nu on the exact initial field",
             sigma.result.first_stage_nu_ratio, 0.0, 1e-12, Check::at_most);
  report.add("Wo 17, D/10, sigma: max nu_sgs / nu over 4 periods (reported; <= Smagorinsky's)",
             sigma.result.max_nu_ratio, 0.0, smag.result.max_nu_ratio, Check::at_most);
  report.add("Wo 17, D/10, sigma: max |u - u_laminar| / u_peak (reported; <= Smagorinsky's)",
             sigma.change, 0.0, smag.change, Check::at_most);
  // Reported, with bounds that only catch a broken model: Smagorinsky's nu_sgs of the shear
  // (C_s Delta)^2 |du/dr| is O(1) nu at D/10 (Delta ~ 1.5 mm, |du/dr| up to ~400 1/s; measured
  // max 5.8, mean 1.4), and it damps the Stokes layers: measured change 0.09-0.10 of u_peak
  // (pressure and convective outlets). The bound 0.25 catches a model on the wrong scale (a
  // Delta in mm gives 1e6 nu), not this known physical damping.
  report.add("Wo 17, D/10, smagorinsky: max nu_sgs / nu (reported)", smag.result.max_nu_ratio, 0.0,
             20.0, Check::at_most);
  report.add("Wo 17, D/10, smagorinsky: mean nu_sgs / nu (reported)", smag.result.mean_nu_ratio,
             0.0, 20.0, Check::at_most);
  report.add("Wo 17, D/10, smagorinsky: max |u - u_laminar| / u_peak (reported)", smag.change, 0.0,
             0.25, Check::at_most);
  report.add("Wo 17, D/10, convective outlet: max axial error / u_peak (reported)",
             find("wo17_d10_convective_outlet").result.max_error, 0.0, 0.3, Check::at_most);
}

}  // namespace

Case womersley_case() {
  return {"womersley",
          "Womersley pipe flow Wo 17 and 4 on tetrahedra: axial profiles at 8 phases vs exact, "
          "LES sigma/smagorinsky on the laminar flow",
          run_case};
}

}  // namespace valsalva::validation
