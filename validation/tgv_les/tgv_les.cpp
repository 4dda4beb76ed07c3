// Taylor-Green vortex Re 1600 with LES (issue 4, verification 4): -dE/dt against the 512^3
// spectral reference for the 4th-order scheme with sigma, WALE, Smagorinsky and no model, and
// the 2nd-order scheme with sigma and no model, at 64^3 to t = 10 (CFL 0.5 on V0); sigma also
// with nu_sgs updated at every RK stage, to measure what holding it over the step (les.update,
// the default) changes. Target (issue 4): 64^3 central4 sigma peak within 5 % in value and 0.5
// in time. CSV: dissipation.csv (every run), table.csv (one row per run); plot.py -> PNG.
// Quick version: the same at 32^3 for central4 sigma only.
// Measured numbers, their run conditions and what they show: README.md in this folder.
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <memory>

#include "validation/case.hpp"
#include "validation/tgv_les/tgv_les_run.hpp"

namespace valsalva::validation {

namespace {

struct Run {
  std::string scheme, model, update;
};

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const auto ref = read_tgv_reference(ctx.refdata_dir / "tgv_re1600" / "spectral_Re1600_512.gdiag");
  std::unique_ptr<fmt::ostream> curves, table;
  if (rank == 0) {
    curves = std::make_unique<fmt::ostream>(
        fmt::output_file((ctx.out_dir / "dissipation.csv").string()));
    curves->print("n,scheme,model,update,t,E,dissipation,dissipation_reference\n");
    table = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "table.csv").string()));
    table->print(
        "n,scheme,model,update,steps,cpu_seconds,peak,peak_time,peak_error_rel,peak_time_error,"
        "max_error_rel,max_nu_sgs_over_nu,max_stability_number,blow_up_time\n");
  }
  const int n = ctx.quick ? 32 : 64;
  std::vector<Run> runs = {{"central4", "sigma", "step"}};
  if (!ctx.quick)
    runs.insert(runs.end(), {{"central4", "sigma", "stage"},
                             {"central4", "wale", "step"},
                             {"central4", "smagorinsky", "step"},
                             {"central4", "none", "step"},
                             {"central2", "sigma", "step"},
                             {"central2", "none", "step"}});
  // operators=order4: the central4 runs with flow.fourth_order_operators (issue 21, target 4).
  const bool order4 = ctx.option("operators", "order2") == "order4";
  double peak_step = 0, peak_stage = 0, reference_peak = 0;
  for (const auto& run : runs) {
    TgvLesSpec spec;
    spec.scheme = run.scheme;
    spec.model = run.model;
    spec.update = run.update;
    spec.fourth_order_operators = order4 && run.scheme == "central4";
    const std::string scheme = run.scheme + (spec.fourth_order_operators ? "+op4" : "");
    const auto r = run_tgv_les(
        spec, n, ctx.comm, ctx.out_dir / "runs" / (scheme + "_" + run.model + "_" + run.update));
    const auto d = tgv_dissipation(r, ref, spec.t_end);
    double max_ratio = 0;
    for (double v : r.max_nu_sgs_over_nu) max_ratio = std::max(max_ratio, v);
    reference_peak = d.reference_peak;
    const double value_error = d.peak / d.reference_peak - 1;
    const double time_error = d.peak_time - d.reference_peak_time;
    if (rank == 0) {
      fmt::print(
          "tgv_les {}^3 {} {} ({}): {} steps, CPU {:.1f} s; peak -dE/dt {:.6f} at t = {:.2f} "
          "(ref {:.6f} at {:.2f}: {:+.2f} %, {:+.2f}); max error {:.3f} of the ref peak; max "
          "nu_sgs/nu {:.3g}; max RK4 stability number {:.3f}{}\n",
          n, scheme, run.model, run.update, r.time.size() - 1, r.cpu_seconds, d.peak, d.peak_time,
          d.reference_peak, d.reference_peak_time, 100 * value_error, time_error, d.max_error,
          max_ratio, r.max_stability_number,
          r.blow_up_time > 0 ? fmt::format("; BLEW UP at t = {:.2f}", r.blow_up_time) : "");
      table->print(
          "{},{},{},{},{},{:.2f},{:.6e},{:.4f},{:.5f},{:.4f},{:.5f},{:.4g},{:.4f},{:.4f}\n", n,
          scheme, run.model, run.update, r.time.size() - 1, r.cpu_seconds, d.peak, d.peak_time,
          value_error, time_error, d.max_error, max_ratio, r.max_stability_number, r.blow_up_time);
      for (std::size_t i = 0; i < d.time.size(); ++i)
        curves->print("{},{},{},{},{:.6f},{:.10e},{:.10e},{:.10e}\n", n, scheme, run.model,
                      run.update, d.time[i], r.energy[i + 1], d.rate[i], d.reference[i]);
      table->flush();
      curves->flush();
    }
    if (run.scheme == "central4" && run.model == "sigma") {
      (run.update == "step" ? peak_step : peak_stage) = d.peak;
      if (run.update != "step") continue;
      const auto name = fmt::format("{}^3 {} sigma", n, scheme);
      report.add(name + ": ran to t_end without blowing up", r.blow_up_time, 0.0, 0.0);
      // Issue 4: 5 % in value and 0.5 in time at 64^3. At 32^3 (quick) the mesh does not
      // resolve the peak: measured -11.8 % at t = 7.94 (reference 8.97) at np 1; 15 % and 1.5
      // keep a margin. Without a model central4 gains energy at 32^3 (bench_tgv_re1600 --n 32
      // --scheme central4: E passes E(0) at t = 8.6 and reaches 1.32 E(0) at t = 10), which the
      // blow-up metric catches. Not a time-step limit: at CFL 0.25 E still peaks at 1.05 E(0),
      // at CFL 0.125 at 1.35 E(0); the RK4 stability number of these runs is 0.33 (x 1.37 for
      // central4's spectral radius: 0.45 < 1). The scheme itself is not energy-conserving.
      report.add(name + ": peak -dE/dt / reference - 1", value_error, 0.0, ctx.quick ? 0.15 : 0.05);
      report.add(name + ": peak time - reference peak time", time_error, 0.0,
                 ctx.quick ? 1.5 : 0.5);
    }
  }
  if (!ctx.quick)
    // Holding nu_sgs over the step (les.update = step) must change the peak by far less than
    // the 5 % target: 1 % of the reference peak.
    report.add(fmt::format("{}^3 central4 sigma: |peak(step) - peak(stage)| / reference peak", n),
               std::abs(peak_step - peak_stage) / reference_peak, 0.0, 0.01, Check::at_most);
}

}  // namespace

Case tgv_les_case() {
  return {"tgv_les",
          "Taylor-Green vortex Re 1600 with LES: -dE/dt vs the spectral reference (central4 and "
          "central2; sigma, WALE, Smagorinsky, none), 64^3 (quick: 32^3)",
          run,
          {CaseOption::choice("operators",
                              "the central4 runs' operators: order2, or order4 "
                              "(flow.fourth_order_operators) (order2)",
                              {"order2", "order4"})}};
}

}  // namespace valsalva::validation
