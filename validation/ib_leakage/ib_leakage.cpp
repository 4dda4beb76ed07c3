// Leakage of the immersed membrane (issue 6, item 4): a thick membrane clamped across a 2D
// channel and loaded by 100 mmHg, the closed aortic valve in diastole (leakage_setup.hpp,
// leakage_run.hpp), for several fluid mesh sizes h and kernel widths. The known weakness of
// immersed methods: the membrane is only a force spread over a few cells, so fluid can pass
// through it, and the pressure jump it holds is smeared over the kernel. The ITBM study this
// design comes from sustained only -21.05 mmHg in the closed phase where its experiment measured
// -93.35 mmHg (../shared/design/architecture.md; a tri-leaflet valve, whose leak is mostly at the
// coaptation lines where three immersed leaflets meet, a path this single clamped membrane does
// not have).
// Measured per run: the leak flow (per unit depth, and as a fraction of the Bernoulli flow of the
// open channel, H sqrt(2 dp / rho)), the jump between region means up- and downstream, the tether
// reaction, the deflection and the static finite-element deflection under the same jump.
// Metrics: force balance (tether reaction = jump x span), the sustained jump on the finest mesh,
// the leak fraction bound and its trend with h, the deflection against the static solution, and
// the steadiness of the leak at the end. Each run is ib_leakage.toml with the run's overrides
// (leakage_setup.hpp), run by run::Simulation like `valsalva run`. Data: runs.csv, history.csv,
// profile.csv, membrane.csv; each run's own outputs (log.csv, structures.csv) in runs/<label>/.
#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/pressure_drop.hpp"
#include "validation/case.hpp"
#include "validation/ib_leakage/leakage_run.hpp"

namespace valsalva::validation {

namespace {

struct Run {
  std::string label;
  LeakageResult result;
};

std::string label_of(const LeakageSetup& s) {
  return fmt::format("h{:g}_w{:g}_t{:g}", s.h * 1e3, s.kernel_width, s.thickness * 1e3);
}

void write_data(const Context& ctx, const std::vector<Run>& runs) {
  auto table = fmt::output_file((ctx.out_dir / "runs.csv").string());
  table.print(
      "label,h,kernel_width,thickness,nodes,markers,dt,dt_min,dt_max,steps,leak,leak_reference,"
      "leak_fraction,leak_change,ramp_leak,jump_mmhg,imposed_mmhg,tether,interior,wall,force_"
      "balance,"
      "deflection,static_deflection,wall_seconds\n");
  auto history = fmt::output_file((ctx.out_dir / "history.csv").string());
  history.print(
      "label,time,inlet_pressure,flow_in,flow_out,area,deflection,jump,tether,interior,wall,"
      "max_marker_speed\n");
  auto profile = fmt::output_file((ctx.out_dir / "profile.csv").string());
  profile.print("label,x,p\n");
  auto shape = fmt::output_file((ctx.out_dir / "membrane.csv").string());
  shape.print("label,shape,x,y\n");
  for (const auto& [label, r] : runs) {
    const auto& s = r.setup;
    table.print(
        "{},{:g},{:g},{:g},{},{},{:.6e},{:.6e},{:.6e},{},{:.6e},{:.6e},{:.6e},{:.3e},{:.4f},{:.6f},"
        "{:.6f},"
        "{:.6e},{:.6e},{:.6e},{:.6f},{:.6e},{:.6e},{:.1f}\n",
        label, s.h, s.kernel_width, s.thickness, r.nodes, r.markers, r.dt, r.dt_min, r.dt_max,
        r.steps, r.leak, r.leak_reference, r.leak / r.leak_reference, r.leak_change, r.ramp_leak,
        r.jump / analysis::pascal_per_mmhg, s.pressure / analysis::pascal_per_mmhg, r.tether,
        r.interior, r.wall, r.interior / (r.jump * r.interior_span), r.deflection,
        r.static_deflection, r.wall_seconds);
    for (const auto& h : r.history)
      history.print(
          "{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e}\n",
          label, h.time, h.inlet_pressure, h.flow_in, h.flow_out, h.area, h.deflection, h.jump,
          h.tether, h.interior, h.wall, h.max_marker_speed);
    for (std::size_t i = 0; i < r.profile_x.size(); ++i)
      profile.print("{},{:.6e},{:.6e}\n", label, r.profile_x[i], r.profile_p[i]);
    for (const auto& [which, line] :
         {std::pair{"final", &r.final_line}, std::pair{"static", &r.static_line}})
      for (Eigen::Index i = 0; i < line->cols(); ++i)
        shape.print("{},{},{:.9e},{:.9e}\n", label, which, (*line)(0, i), (*line)(1, i));
  }
}

// Tolerances from the measured sweep: the 20 ms ramp still leaves a column oscillation of about
// +-10 % of the load (period about 8 ms, see the plot), which the 10 ms window means carry at
// the 1-2 % level; the quick run (10 ms ramp, 5 ms window) gets twice the tolerance.
void add_metrics(const Context& ctx, const std::vector<Run>& runs, Report& report) {
  const double loose = ctx.quick ? 2.0 : 1.0;
  for (const auto& [label, r] : runs)
    // Fluid at rest between the regions: the membrane's force on the interior nodes balances
    // the jump over their height H - h (the wall nodes' velocity is imposed: the force spread
    // onto them is taken by the wall, like the pressure gradient over their half cells).
    report.add(label + ": membrane force on interior nodes / (sustained jump x (H - h))",
               r.interior / (r.jump * r.interior_span), 1.0, 0.03 * loose);
  const auto& fine = runs[ctx.quick ? 0 : 2];
  const auto& r = fine.result;
  const double imposed = r.setup.pressure;
  report.add(fine.label + ": sustained jump / imposed 100 mmHg", r.jump / imposed, 1.0,
             0.03 * loose);
  // The reference study's ITBM simulation held 21.05 of the 93.35 mmHg its experiment measured.
  report.add(fine.label + ": sustained jump / imposed, at least the reference ITBM's 21.05/93.35",
             r.jump / imposed, 21.05 / 93.35, 0.0, Check::at_least);
  double worst = 0;
  for (const auto& run : runs)
    worst = std::max(worst, std::abs(run.result.leak) / run.result.leak_reference);
  // Measured 2.8e-4 .. 5.7e-3 over the full sweep: the steady leak stays below 1 %.
  report.add("largest |leak| / Bernoulli flow of the open channel, all runs", worst, 0.0, 1e-2,
             Check::at_most);
  if (!ctx.quick) {
    // Refinement at the same kernel width (h = 1 -> 0.5 mm): measured 8x less leak.
    const auto& coarse = runs[0].result;
    report.add("leak(h = 0.5 mm) / leak(h = 1 mm), kernel width 4 h (at most 1: falls with h)",
               r.leak / coarse.leak, 1.0, 0.0, Check::at_most);
  }
  report.add(fine.label + ": leak change between the window halves / Bernoulli flow", r.leak_change,
             0.0, 1e-3 * loose, Check::at_most);
  // The static solution under the same jump is the membrane's equilibrium (hard clamp instead
  // of the tether; the IB membrane's load is smeared over the kernel instead of on one face).
  report.add(fine.label + ": deflection / static finite-element deflection under the same jump",
             r.deflection / r.static_deflection, 1.0, 0.03 * loose);
}

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  auto setup = [&](double h, double width) {
    LeakageSetup s;
    s.h = h, s.kernel_width = width;
    // Quick: 8 cells across, a 20 mm channel and a 10 ms ramp (about 17 s of CPU).
    if (ctx.quick)
      s.ramp = 0.01, s.t_end = 0.02, s.depth_cells = 6, s.upstream = 7.5e-3, s.downstream = 12.5e-3;
    return s;
  };
  std::vector<LeakageSetup> setups;
  if (ctx.quick)
    setups = {setup(1.25e-3, 4)};
  else
    setups = {setup(1e-3, 4), setup(2e-3 / 3, 4), setup(0.5e-3, 4), setup(1e-3, 3), setup(1e-3, 6)};
  std::vector<Run> runs;
  for (const auto& s : setups) {
    const auto label = label_of(s);
    runs.push_back({label, run_leakage(s, ctx.out_dir / "runs" / label, ctx.comm)});
    const auto& r = runs.back().result;
    if (rank == 0)
      fmt::print(
          "ib_leakage {}: {} nodes, {} markers, dt {:.3e} s ({:.3e} .. {:.3e}), {} steps, leak "
          "{:.4e} m^2/s ({:.3e} of Bernoulli, change {:.1e}; leaked in the ramp {:.3f} of the "
          "displaced area), jump {:.2f} mmHg, force on "
          "interior nodes / (jump (H - h)) {:.4f}, on wall nodes / interior {:.4f}, tether / "
          "interior "
          "{:.4f}, deflection {:.4f} mm (static {:.4f}), {:.0f} s\n",
          runs.back().label, r.nodes, r.markers, r.dt, r.dt_min, r.dt_max, r.steps, r.leak,
          r.leak / r.leak_reference, r.leak_change, r.ramp_leak, r.jump / analysis::pascal_per_mmhg,
          r.interior / (r.jump * r.interior_span), r.wall / r.interior, r.tether / r.interior,
          r.deflection * 1e3, r.static_deflection * 1e3, r.wall_seconds);
  }
  if (rank == 0) write_data(ctx, runs);
  add_metrics(ctx, runs, report);
}

}  // namespace

Case ib_leakage_case() {
  return {"ib_leakage",
          "Thick membrane clamped across a channel under 100 mmHg (closed valve): leak flow and "
          "the pressure jump the immersed membrane sustains, for several h and kernel widths",
          run};
}

}  // namespace valsalva::validation
