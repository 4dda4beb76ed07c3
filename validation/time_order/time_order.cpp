// Time accuracy on a nonlinear flow (issue 21, target 7): the 3D Taylor-Green vortex at Re 1600
// (initial.type = taylor_green_3d) on a periodic 32^3 box (quick: 16^3) to t = 2 (quick: 1),
// with dt halved four times (5 levels) from the coarsest, against a reference run of the same
// time integrator at dt_finest / 8. Variants: time.scheme = rk4_jameson (the default) and
// rk4_classic, each with and without time.project_stages (flow/time_scheme.hpp,
// flow/projection_rk4.hpp). Every run is the scene validation/time_order/time_order.toml with
// overrides, run through run::Simulation (`valsalva run`'s path) with a fixed time step; Poisson
// tolerance 1e-10 (the errors stay above 1e-7, 1e-3 relative to them).
// Reported per variant and dt: the velocity L2 error against the reference (absolute and
// relative to the reference's L2 norm), the observed order per halving, the CPU time (summed
// over ranks); and the CPU time at equal error relative to rk4_jameson (a power-law fit
// log cpu = a + s log e per variant, evaluated at rk4_jameson's error of the middle level).
// The spatial error is the same in every run of one variant and cancels: this measures the
// time integration alone (plus the splitting of the projection).
// Asserted: the observed order of the two finest levels of each variant >= 1.8 (every variant
// is 2nd order: the splitting of the incremental projection; 1.8 leaves room for the reference
// run's own error, which moves the finest pair's order by (4 - 1/64)/(1 - 1/64), +0.02, and for
// the pre-asymptotic range of the quick run); rk4_classic's error within 2 % of rk4_jameson's
// and its CPU time at equal error within 0.5 of it (timing noise); with project_stages, an error at
// most rk4_jameson's and a CPU time at equal error at least rk4_jameson's (the reason the default
// is rk4_jameson without stage projections: the check fails when that stops being true).
// Measured numbers, their run conditions and what they show: README.md in this folder.
// CSV: errors.csv; plot.py makes time_order.png (error against dt and against CPU time).
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <memory>
#include <vector>

#include "validation/case.hpp"
#include "validation/time_order/time_order_run.hpp"

namespace valsalva::validation {

namespace {

struct Level {
  TimeOrderRun run;
  double error = 0, relative = 0, order = 0;  // order: against the previous (coarser) level
};

// CPU time at error `target` from the least-squares line log cpu = a + s log e.
double cpu_at_error(const std::vector<Level>& levels, double target) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& l : levels) {
    const double x = std::log(l.error), y = std::log(l.run.cpu_seconds);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double s = (n * sxy - sx * sy) / (n * sxx - sx * sx), a = (sy - s * sx) / n;
  return std::exp(a + s * std::log(target));
}

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const int n = ctx.option_int("n", ctx.quick ? 16 : 32);
  const double t_end = ctx.option_real("t_end", ctx.quick ? 1.0 : 2.0);
  const int coarse = ctx.option_int("coarse_steps", ctx.quick ? 5 : 20);
  const int levels = ctx.option_int("levels", 5);
  const int factor = ctx.option_int("reference_factor", 8);
  const double velocity = ctx.option_real("velocity", 1.0);
  std::unique_ptr<fmt::ostream> csv;
  if (rank == 0) {
    csv = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "errors.csv").string()));
    csv->print(
        "variant,n,t_end,level,steps,dt,velocity_l2,relative_l2,order,cpu_seconds,wall_seconds,"
        "max_poisson_iterations\n");
  }
  const std::vector<TimeVariant> variants{{flow::TimeScheme::rk4_jameson, false},
                                          {flow::TimeScheme::rk4_classic, false},
                                          {flow::TimeScheme::rk4_jameson, true},
                                          {flow::TimeScheme::rk4_classic, true}};
  std::vector<std::vector<Level>> all;
  for (const auto& variant : variants) {
    TimeOrderRunSpec spec;
    spec.variant = variant;
    spec.cells = n;
    spec.velocity = velocity;
    spec.t_end = t_end;
    spec.steps = coarse * (1 << (levels - 1)) * factor;
    // The run directories (log.csv, resolved_scene.toml): runs/<variant>_<steps>.
    auto dir = [&](int steps) {
      return ctx.out_dir / "runs" / fmt::format("{}_{}", variant.name(), steps);
    };
    const auto reference = run_time_order(spec, dir(spec.steps), ctx.comm);
    const double norm = velocity_l2_difference(reference, nullptr, ctx.comm);
    std::vector<Level> results;
    for (int l = 0; l < levels; ++l) {
      spec.steps = coarse << l;
      Level level;
      level.run = run_time_order(spec, dir(spec.steps), ctx.comm);
      level.error = velocity_l2_difference(level.run, &reference, ctx.comm);
      level.relative = level.error / norm;
      if (l > 0) level.order = std::log2(results.back().error / level.error);
      if (csv)
        csv->print("{},{},{},{},{},{:.6e},{:.6e},{:.6e},{:.4f},{:.3f},{:.3f},{}\n", variant.name(),
                   n, t_end, l, level.run.steps, level.run.dt, level.error, level.relative,
                   level.order, level.run.cpu_seconds, level.run.wall_seconds,
                   level.run.max_poisson_iterations);
      if (csv) csv->flush();
      results.push_back(std::move(level));
    }
    if (csv)
      csv->print("{},{},{},reference,{},{:.6e},0,0,0,{:.3f},{:.3f},{}\n", variant.name(), n, t_end,
                 reference.steps, reference.dt, reference.cpu_seconds, reference.wall_seconds,
                 reference.max_poisson_iterations);
    report.add(variant.name() + ": observed order, two finest dt", results.back().order, 2.0, 0.2,
               Check::at_least);
    all.push_back(std::move(results));
  }
  // Stored norm: rk4_jameson's error at the finest dt of the default runs (measured 2026-12-03,
  // 1 and 2 ranks agree to 7 digits; 2 % flags any change of the scheme, the operators or the
  // set-up, far above the Poisson tolerance's effect).
  if (n == (ctx.quick ? 16 : 32) && t_end == (ctx.quick ? 1.0 : 2.0) &&
      coarse == (ctx.quick ? 5 : 20) && levels == 5 && factor == 8 && velocity == 1.0) {
    const double stored = ctx.quick ? 1.160821e-05 : 3.841679e-06;
    report.add("rk4_jameson: error at the finest dt / stored", all[0].back().error / stored, 1.0,
               0.02);
  }
  // Equal error: rk4_jameson's at the middle level (inside every variant's range of errors).
  const double target = all[0][static_cast<std::size_t>(levels / 2)].error;
  const double cpu_jameson = cpu_at_error(all[0], target);
  for (std::size_t v = 1; v < variants.size(); ++v) {
    const double error_ratio = all[v].back().error / all[0].back().error;
    const double cpu_ratio = cpu_at_error(all[v], target) / cpu_jameson;
    const std::string name = variants[v].name();
    if (!variants[v].project_stages) {
      // The same splitting error dominates both schemes: equal errors (measured 1.001 quick,
      // 1.007 full, see docs/validation.md), and the same work per step: the CPU ratio is 1 up
      // to the timing noise of a shared machine (0.89 full; the quick runs of the two rank
      // counts in parallel under ctest -j2 move it by tens of %), so only within 0.5.
      report.add(name + ": error / rk4_jameson's at the finest dt", error_ratio, 1.0, 0.02);
      if (!ctx.quick)
        report.add(name + ": CPU / rk4_jameson's at equal error", cpu_ratio, 1.0, 0.5);
    } else {
      // Projecting the stages removes part of the splitting error, never adds to it; it costs
      // three Poisson solves more per step, more than the smaller error saves (the default
      // stays rk4_jameson without it while this ratio is above 1).
      report.add(name + ": error / rk4_jameson's at the finest dt", error_ratio, 1.0, 0.0,
                 Check::at_most);
      if (!ctx.quick)
        report.add(name + ": CPU / rk4_jameson's at equal error", cpu_ratio, 1.0, 0.0,
                   Check::at_least);
    }
    // The quick version runs in `make test` beside other tests (and its np 2 twin): CPU times
    // there are not a measurement (a classic/jameson ratio of 1.55 was seen under ctest -j2), so
    // it prints the ratio and checks it only in the full version (speed claims belong to
    // benchmark-like runs on a quiet machine).
    if (ctx.quick && rank == 0)
      fmt::print(
          "time_order: {} CPU / rk4_jameson's at equal error {:.3g} (not checked in --quick)\n",
          name, cpu_ratio);
  }
}

}  // namespace

Case time_order_case() {
  return {"time_order",
          "3D Taylor-Green Re 1600, 32^3, t 2: temporal order of the velocity and error vs CPU "
          "time of rk4_jameson and rk4_classic, with and without time.project_stages",
          run,
          {CaseOption::integer("n", "cells per side (default 32, quick 16)", 4, 256),
           CaseOption::real("t_end", "end time in s (default 2, quick 1)", 1e-3, 20),
           CaseOption::integer("coarse_steps", "steps of the coarsest dt (default 20, quick 5)", 1,
                               100000),
           CaseOption::integer("levels", "number of dt (each half the previous; default 5)", 2, 8),
           CaseOption::integer("reference_factor", "reference dt = finest dt / this (default 8)", 2,
                               64),
           CaseOption::real("velocity",
                            "U0 in m/s at fixed nu = 1/1600 (default 1: Re 1600; small U0 makes "
                            "the problem nearly linear)",
                            1e-8, 10)}};
}

}  // namespace valsalva::validation
