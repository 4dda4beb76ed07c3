// Verification 2 of issue 4 (the Sigma model on a laminar flow) on Womersley's own problem: a
// streamwise-periodic pipe driven by an oscillating pressure gradient (set-up: periodic_run.hpp),
// Wo = 17, on a triangulated disk extruded into identical prism layers. There the parallel flow
// u_z(x, y) e_z is a discrete solution: every operator of a z-invariant field on a z-invariant
// mesh gives z-invariant results, the convective and Laplacian terms have no transverse
// component, the divergence vanishes (the vertical dual faces of the horizontal edges carry no
// z flux, the two vertical edges cancel), so dp and the transverse velocity stay at round-off.
// The Sigma operator is zero for a velocity gradient of rank one (sigma2 = sigma3 = 0), so with
// sigma the run must repeat the laminar one: both within 1e-8 (issue 4, item 2).
// Split prisms (io/prism_split.hpp, the same diagonals in every layer) keep it too, measured:
// each of a prism's three tetrahedra holds one vertical edge, so the linear interpolant of
// z-invariant nodal data has no z derivative, and the median-dual operators on tetrahedra are
// the P1 ones (Barth, VKI LS 1994-05). So prisms are not needed; the split mesh also gets the
// consistent P1 Poisson weights (on prisms flow::poisson_weights falls back to the two-point
// weight, not consistent where S_jk is not parallel to the edge, but dp stays at round-off here).
// Measured against the exact solution (flow/womersley.hpp): max and L2 error of u_z over all
// nodes at 8 phases of the 4th period, on D/10, D/20, D/40, and the observed order.
// Driven by the exact pressure gradient, the run carries no imposed flow rate: its flux misses
// Q(t) by up to 1.1 % of pi R^2 u_peak at D/20 while the core stays exact; the inlet-driven pipe
// must carry Q, see validation/womersley's header (PeriodicSetup::flux_driven, a study option).
// Tables: levels.csv; samples.csv, plotted by plot.py into womersley_periodic.png.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "validation/case.hpp"
#include "validation/womersley_periodic/periodic_run.hpp"

namespace valsalva::validation {

namespace {

struct Run {
  std::string label;
  PeriodicSetup setup;
  PeriodicResult result;
  double change = 0;  // LES: max |u - u_none| / u_peak at the end (same mesh and partition)
};

const Run& find(const std::vector<Run>& runs, const std::string& label) {
  const auto it =
      std::find_if(runs.begin(), runs.end(), [&](const Run& r) { return r.label == label; });
  if (it == runs.end()) throw std::logic_error("womersley_periodic: no run " + label);
  return *it;
}

PeriodicSetup setup(double npd, bool split, const std::string& les, int periods) {
  PeriodicSetup s;
  s.nodes_per_diameter = npd, s.split = split, s.les_model = les, s.periods = periods;
  return s;
}

void write_samples(const Context& ctx, const std::vector<Run>& runs) {
  std::ofstream out(ctx.out_dir / "samples.csv"), curves(ctx.out_dir / "curves.csv");
  out << "case,npd,time,r,u,u_exact,u_peak,radius\n";
  curves << "case,time,r,u_exact\n";
  for (const auto& run : runs) {
    if (run.setup.les_model != "none" || run.setup.split) continue;
    const auto& s = run.result.samples;
    for (std::size_t i = 0; i + 3 < s.size(); i += 4)
      out << fmt::format("{},{},{:.6f},{:.6e},{:.9e},{:.9e},{:.9e},{:.9e}\n", run.label,
                         run.setup.nodes_per_diameter, s[i], s[i + 1], s[i + 2], s[i + 3],
                         run.result.u_peak, run.result.radius);
    std::set<double> times;
    for (std::size_t i = 0; i < s.size(); i += 4) times.insert(s[i]);
    for (const double t : times)
      for (int k = 0; k <= 100; ++k) {
        const double r = run.result.radius * k / 100;
        curves << fmt::format("{},{:.6f},{:.6e},{:.9e}\n", run.label, t, r,
                              run.result.exact.velocity(r, t));
      }
  }
}

void run_case(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const int periods = ctx.quick ? 2 : 4;
  std::vector<Run> runs;
  const auto add = [&](const std::string& label, double npd, bool split, const std::string& les) {
    runs.push_back({label, setup(npd, split, les, periods), {}, 0});
  };
  add("prism_d10", 10, false, "none");
  add("prism_d10_sigma", 10, false, "sigma");
  add("prism_d10_smagorinsky", 10, false, "smagorinsky");
  add("tetra_d10", 10, true, "none");
  add("tetra_d10_sigma", 10, true, "sigma");
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
           "wall_s\n";
  }
  for (auto& run : runs) {
    run.result = run_periodic_womersley(run.setup, ctx.comm);
    const auto& r = run.result;
    if (run.setup.les_model != "none") {
      const auto& twin = find(runs, run.label.substr(0, run.label.rfind('_')));
      for (std::size_t i = 0; i < r.final_velocity.size(); ++i)
        run.change =
            std::max(run.change, std::abs(r.final_velocity[i] - twin.result.final_velocity[i]));
      run.change /= twin.result.u_peak;
    }
    if (rank != 0) continue;
    csv << fmt::format(
        "{},{},{},{},{},{},{:.6e},{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
        "{:.6e},{:.3e},{:.1f}\n",
        run.label, run.setup.nodes_per_diameter, run.setup.split ? "tetra" : "prism",
        run.setup.les_model, r.nodes, r.steps, r.dt, r.u_peak, r.max_error, r.l2_error,
        r.transverse, r.max_nu_ratio, r.mean_nu_ratio, run.change, r.max_divergence, r.wall);
    csv.flush();
    fmt::print(
        "womersley_periodic {}: {} nodes, {} steps dt {:.3e} s, max error {:.3e} L2 {:.3e}, "
        "transverse {:.2e} of u_peak {:.4f} m/s, nu_sgs/nu max {:.3e} mean {:.3e}, velocity "
        "change {:.3e}, max |div u| {:.2e} 1/s, {:.1f} s\n",
        run.label, r.nodes, r.steps, r.dt, r.max_error, r.l2_error, r.transverse, r.u_peak,
        r.max_nu_ratio, r.mean_nu_ratio, run.change, r.max_divergence, r.wall);
  }
  if (rank == 0) write_samples(ctx, runs);
  const std::string level = ctx.quick ? "d10" : "d20";
  const auto& none = find(runs, "prism_" + level).result;
  const auto& sigma = find(runs, "prism_" + level + "_sigma");
  const auto& smag = find(runs, "prism_" + level + "_smagorinsky");
  const std::string where = fmt::format("Wo 17, prisms D/{}, {} periods", level.substr(1), periods);
  report.add(where + ": max |u_x, u_y| / u_peak without a model", none.transverse, 0.0, 1e-12,
             Check::at_most);
  report.add(where + ", sigma: max nu_sgs / nu over all steps and stages",
             sigma.result.max_nu_ratio, 0.0, 1e-8, Check::at_most);
  report.add(where + ", sigma: max |u_sigma - u_none| / u_peak at the end", sigma.change, 0.0, 1e-8,
             Check::at_most);
  report.add(where + ", smagorinsky: max nu_sgs / nu (reported)", smag.result.max_nu_ratio, 0.0,
             20.0, Check::at_most);
  report.add(where + ", smagorinsky: mean nu_sgs / nu (reported)", smag.result.mean_nu_ratio, 0.0,
             20.0, Check::at_most);
  report.add(where + ", smagorinsky: max |u_smag - u_none| / u_peak (reported)", smag.change, 0.0,
             0.25, Check::at_most);
  const auto& tetra = find(runs, "tetra_" + level + "_sigma");
  report.add(where + ", split tetrahedra: max |u_x, u_y| / u_peak without a model",
             find(runs, "tetra_" + level).result.transverse, 0.0, 1e-12, Check::at_most);
  report.add(where + ", split tetrahedra, sigma: max nu_sgs / nu", tetra.result.max_nu_ratio, 0.0,
             1e-8, Check::at_most);
  report.add(where + ", split tetrahedra, sigma: max |u_sigma - u_none| / u_peak", tetra.change,
             0.0, 1e-8, Check::at_most);
  if (ctx.quick) {
    // D/10 over 2 periods: measured max 0.038, L2 0.017 of u_peak; bounds = measured + 30 %. A
    // wrong drive (amplitude, phase, sign) gives O(0.1 - 1): Smagorinsky's damping alone 0.18.
    report.add(where + ": max axial error / u_peak (last period, 8 phases)", none.max_error, 0.0,
               0.05, Check::at_most);
    report.add(where + ": L2 axial error / u_peak", none.l2_error, 0.0, 0.025, Check::at_most);
    return;
  }
  report.add(where + ", wale: max nu_sgs / nu (reported)",
             find(runs, "prism_d20_wale").result.max_nu_ratio, 0.0, 1e-8, Check::at_most);
  // Against the exact solution, 4th period: measured max 3.7 %, 2.1 %, 0.70 % and L2 1.65 %,
  // 0.64 %, 0.18 % of u_peak at D/10, D/20, D/40. The max sits in the Stokes layer (thickness
  // sqrt(2 nu / w) = 0.083 R), which D/10 (h = 0.2 R) does not resolve: D/10 -> D/20 is
  // pre-asymptotic (orders 0.8 max, 1.4 L2, reported); D/20 -> D/40 gives 1.57 and 1.83, the
  // second order of the scheme approached (bound 1.5). Error bounds: the D/40 max and the D/20
  // L2 below 1 %, half the issue-3 target of 2 % at D/20 for the inlet-driven pipe.
  report.add("Wo 17, prisms D/20: max axial error / u_peak (reported)", none.max_error, 0.0, 0.03,
             Check::at_most);
  report.add("Wo 17, prisms D/20: L2 axial error / u_peak", none.l2_error, 0.0, 0.01,
             Check::at_most);
  report.add("Wo 17, prisms D/40: max axial error / u_peak",
             find(runs, "prism_d40").result.max_error, 0.0, 0.01, Check::at_most);
  report.add("Wo 17, prisms D/40: L2 axial error / u_peak", find(runs, "prism_d40").result.l2_error,
             0.0, 0.01, Check::at_most);
  const auto order = [&](const std::string& a, const std::string& b, bool l2) {
    const auto &c = find(runs, a).result, &f = find(runs, b).result;
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

}  // namespace

Case womersley_periodic_case() {
  return {"womersley_periodic",
          "Womersley's pressure-gradient driven periodic pipe (Wo 17) on extruded prisms: exact "
          "parallel flow, sigma vanishes (nu_sgs/nu, u_sigma - u_none below 1e-8), Smagorinsky "
          "reported, analytic error and order",
          run_case};
}

}  // namespace valsalva::validation
