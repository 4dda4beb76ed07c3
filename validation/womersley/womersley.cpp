// Womersley flow in a rigid straight pipe (Womersley, J. Physiol. 127, 553-563, 1955; issue 3
// item 3 and issue 4 item 2): tetrahedral pipe meshes at D/10, D/20 (the target level) and finer,
// Wo = 17 (the reference experiment: blood analogue, 60 bpm, D = 24.5 mm) and Wo = 4, sine flow
// rate with the exact Womersley inlet profile, pressure outlet (the exact solution has p uniform
// over every section; a convective outlet freezes du/dt there, see outlet_*.csv). Set-up and
// sampling: womersley_run.hpp. Measured: max and L2 error of the axial velocity on the
// mid-length section at 8 phases of the 4th period, relative to the peak centreline velocity.
// LES on the laminar flow: the sigma model must vanish (its operator is zero for a pure shear
// du_z/dr), Smagorinsky's spurious nu_sgs is reported. Tables: levels.csv, les.csv;
// profiles: profiles.csv and curves.csv, plotted by plot.py into womersley_profiles.png.
#include "flow/womersley.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>

#include "validation/case.hpp"
#include "validation/womersley/womersley_run.hpp"

namespace valsalva::validation {

namespace {

struct Run {
  std::string label;
  WomersleySetup setup;
  WomersleyResult result;
};

void write_profiles(const Context& ctx, const std::vector<Run>& runs) {
  std::ofstream p(ctx.out_dir / "profiles.csv"), c(ctx.out_dir / "curves.csv");
  p << "case,wo,npd,time,x,y,r,u,u_exact,u_peak,radius\n";
  c << "case,wo,time,s,u_exact,u_peak\n";
  for (const auto& run : runs) {
    const auto& r = run.result;
    const double nu = r.nu, period = 1.0,
                 q0 = 5 * 2 * r.radius * std::numbers::pi * r.radius * r.radius;
    const auto exact = flow::Womersley::from_sine(r.radius, nu, q0, q0, period, 0.0);
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
  std::vector<Run> runs;
  if (ctx.quick) {
    runs = {{"wo4_d10", setup(4, 10, pressure, "none"), {}},
            {"wo4_d10_sigma", setup(4, 10, pressure, "sigma"), {}}};
    for (auto& run : runs) run.setup.sample_period = 0;  // the first period only
    if (const char* e = std::getenv("WOM_EXPLORE")) {
      runs.clear();
      std::stringstream ss(e);
      for (std::string item; std::getline(ss, item, ';');) {
        double wo = 0, npd = 0, cfl = 0.4, len = 2;
        char o = 'p';
        char les[32] = "none";
        std::sscanf(item.c_str(), "%lf,%lf,%c,%lf,%lf,%31s", &wo, &npd, &o, &cfl, &len, les);
        std::string label = item;
        std::replace(label.begin(), label.end(), ',', '_');
        runs.push_back({label, setup(wo, npd, o == 'c' ? convective : pressure, les), {}});
        runs.back().setup.cfl = cfl;
        runs.back().setup.length_in_diameters = len;
      }
    }
  } else {
    runs = {{"wo17_d10", setup(17, 10, pressure, "none"), {}},
            {"wo17_d20", setup(17, 20, pressure, "none"), {}},
            {"wo4_d10", setup(4, 10, pressure, "none"), {}},
            {"wo4_d20", setup(4, 20, pressure, "none"), {}},
            {"wo17_d10_convective", setup(17, 10, convective, "none"), {}},
            {"wo17_d10_sigma", setup(17, 10, pressure, "sigma"), {}},
            {"wo17_d10_smagorinsky", setup(17, 10, pressure, "smagorinsky"), {}}};
  }
  std::ofstream csv;
  if (rank == 0) {
    csv.open(ctx.out_dir / "levels.csv");
    csv << "case,wo,nodes_per_diameter,outlet,les,nodes,steps,dt,u_peak,max_error,l2_error,"
           "transverse,max_nu_sgs_over_nu,mean_nu_sgs_over_nu,max_divergence,wall_s\n";
  }
  for (auto& run : runs) {
    run.result = run_womersley(run.setup, ctx.comm);
    const auto& r = run.result;
    if (rank != 0) continue;
    const bool conv = run.setup.outlet == convective;
    csv << fmt::format(
        "{},{},{},{},{},{},{},{:.6e},{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.3e},"
        "{:.1f}\n",
        run.label, run.setup.womersley, run.setup.nodes_per_diameter,
        conv ? "convective" : "pressure", run.setup.les_model, r.nodes, r.steps, r.dt, r.u_peak,
        r.max_error, r.l2_error, r.transverse, r.max_nu_ratio, r.mean_nu_ratio, r.max_divergence,
        r.wall);
    csv.flush();
    fmt::print(
        "womersley {}: {} nodes, {} steps dt {:.3e} s, max error {:.4f} L2 {:.4f} transverse "
        "{:.2e} of u_peak {:.4f} m/s, nu_sgs/nu max {:.3e} mean {:.3e}, {:.0f} s\n",
        run.label, r.nodes, r.steps, r.dt, r.max_error, r.l2_error, r.transverse, r.u_peak,
        r.max_nu_ratio, r.mean_nu_ratio, r.wall);
  }
  // Velocity change of an LES run against its laminar twin (same mesh and partition).
  auto change = [&](const Run& les, const Run& laminar) {
    double worst = 0;
    for (std::size_t i = 0; i < les.result.final_velocity.size(); ++i)
      worst = std::max(worst,
                       std::abs(les.result.final_velocity[i] - laminar.result.final_velocity[i]));
    return worst / laminar.result.u_peak;
  };
  if (rank == 0) write_profiles(ctx, runs);

  if (ctx.quick) {
    // Quick: Wo = 4 on D/10 (1.1 k nodes), first period. Measured max error 0.0xx; the bound
    // 0.05 is the D/10 level's expected second-order error (4x the 2 % target at D/20).
    report.add("Wo 4, D/10: max axial error / u_peak (1st period)", runs[0].result.max_error, 0.0,
               0.05, Check::at_most);
    report.add("Wo 4, D/10, sigma: max nu_sgs / nu", runs[1].result.max_nu_ratio, 0.0, 1e-8,
               Check::at_most);
    report.add("Wo 4, D/10, sigma: max |u - u_laminar| / u_peak", change(runs[1], runs[0]), 0.0,
               1e-8, Check::at_most);
    return;
  }
  const auto& wo17 = runs[1].result;
  const auto& wo4 = runs[3].result;
  report.add("Wo 17, D/20: max axial error / u_peak (4th period, 8 phases)", wo17.max_error, 0.0,
             0.02, Check::at_most);
  report.add("Wo 4, D/20: max axial error / u_peak (4th period, 8 phases)", wo4.max_error, 0.0,
             0.02, Check::at_most);
  // L2 errors are below the max errors by construction; the 2 % bound holds for them too.
  report.add("Wo 17, D/20: L2 axial error / u_peak", wo17.l2_error, 0.0, 0.02, Check::at_most);
  report.add("Wo 4, D/20: L2 axial error / u_peak", wo4.l2_error, 0.0, 0.02, Check::at_most);
  report.add("Wo 17: observed order of the max error, D/10 -> D/20",
             std::log(runs[0].result.max_error / wo17.max_error) / std::log(2.0), 2.0, 1.0,
             Check::at_least);
  // Issue 4 item 2: sigma vanishes on the laminar pipe flow.
  report.add("Wo 17, D/10, sigma: max nu_sgs / nu", runs[5].result.max_nu_ratio, 0.0, 1e-8,
             Check::at_most);
  report.add("Wo 17, D/10, sigma: max |u - u_laminar| / u_peak", change(runs[5], runs[0]), 0.0,
             1e-8, Check::at_most);
  // Smagorinsky is reported, not required to vanish (it does not: |S| of the shear); bound at
  // nu_sgs/nu = 10, beyond which the laminar profile would be visibly damped.
  report.add("Wo 17, D/10, smagorinsky: max nu_sgs / nu (reported)", runs[6].result.max_nu_ratio,
             0.0, 10.0, Check::at_most);
  report.add("Wo 17, D/10, smagorinsky: mean nu_sgs / nu (reported)", runs[6].result.mean_nu_ratio,
             0.0, 10.0, Check::at_most);
  report.add("Wo 17, D/10, smagorinsky: max |u - u_laminar| / u_peak (reported)",
             change(runs[6], runs[0]), 0.0, 1.0, Check::at_most);
  report.add("Wo 17, D/10, convective outlet: max axial error / u_peak (reported)",
             runs[4].result.max_error, 0.0, 1.0, Check::at_most);
}

}  // namespace

Case womersley_case() {
  return {"womersley",
          "Womersley pipe flow Wo 17 and 4 on tetrahedra: axial profiles at 8 phases vs exact, "
          "LES sigma/smagorinsky on the laminar flow",
          run_case};
}

}  // namespace valsalva::validation
