// Long-run stability (flow-solver issue, verification 7; issue 21, target 3): 10^5 steps of a
// periodic flow at the largest time step the RK4 stability estimate admits (sigma = 1 in
// flow/run_diagnostics.hpp, recomputed every step), with the non-dissipative centred scheme, on
// split tetrahedra and on 20 % perturbed tetrahedra, the latter with the solver's default
// incremental projection and with periodic_pressure_damping (all three asserted).
// Flow (validation/stability/stability.toml, run by `valsalva run`'s Simulation): Kolmogorov
// forcing f = F sin(k y) e_x in the unit periodic box ([forcing], its discrete mean removed),
// started from rest plus a divergence-free perturbation, Re = U / (nu k) = 16 (below the flow's
// linear-stability limit, so the physical answer is the steady laminar profile U sin(k y),
// U = F / (rho nu k^2), reached after a few 1/(nu k^2)); time.stability_fraction = sigma. Checks:
// no blow-up (finite energy, bounded divergence), the steady kinetic energy against the analytic
// U^2/4 within issue 21's 5 %, and no drift: the energy's relative change over the second half of
// the run.
// Measured numbers, their run conditions and what they show: README.md in this folder.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "flow/run_diagnostics.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

// quick_steps: the quick level's run length. The undamped incremental projection on perturbed
// tetrahedra leaves a start-up transient in pressure modes the wide gradient hardly sees, which
// decays by e every ~2700 steps (README.md); its drift over the second half falls below 1e-9
// only after some 45000 steps.
void run_stability(const Context& ctx, Report& report, double perturbation,
                   const std::string& label, bool damping, int quick_steps) {
  const int steps = ctx.quick ? quick_steps : 100000;
  const double sigma = ctx.option_real("sigma", 1.0);
  const double u_max = 1.0;  // the laminar amplitude of stability.toml
  std::ofstream csv;
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (rank == 0) {
    csv.open(ctx.out_dir / ("energy_" + label + ".csv"));
    csv << "step,time,dt,energy\n";
  }
  double e_half = 0, e_end = 0, dt_min = 1e300, dt_max = 0, t_previous = 0;
  bool finite = true;
  double volume = 0;
  SceneRun measure;
  auto mean_energy = [&](const run::Simulation& sim) {
    return flow::kinetic_energy(sim.local(), 1.0, sim.state().velocity) / volume;
  };
  measure.at_start = [&](const run::Simulation& sim) {
    double v = 0;
    for (int i = 0; i < sim.local().num_owned; ++i) v += sim.local().volume[i];
    volume = sim.local().comm.sum(v);
  };
  measure.observer = [&](const run::Simulation& sim, std::int64_t s) {
    const double t = sim.state().time, dt = t - t_previous;
    t_previous = t;
    dt_min = std::min(dt_min, dt);
    dt_max = std::max(dt_max, dt);
    if (s == steps / 2) e_half = mean_energy(sim);
    if (s % (steps / 200) == 0 || s == steps) {
      const double e = mean_energy(sim);
      finite = finite && std::isfinite(e);
      if (csv.is_open()) csv << fmt::format("{},{:.6g},{:.6g},{:.12e}\n", s, t, dt, e);
    }
  };
  measure.at_end = [&](const run::Simulation& sim) { e_end = mean_energy(sim); };
  const auto result = run_scene_file(case_scene("stability", "stability.toml"),
                                     {fmt::format("mesh.box.perturbation={}", perturbation),
                                      fmt::format("poisson.periodic_damping={}", damping),
                                      fmt::format("time.stability_fraction={:.17g}", sigma),
                                      fmt::format("time.max_steps={}", steps)},
                                     ctx.out_dir / "runs" / label, ctx.comm, measure);
  // |div v| h / max|v| at each node and step, the largest over the run: the step's own h and
  // speed, so the start from 0.1 U weighs more than against the laminar U.
  const double div_number = result.summary.max_divergence_number;
  const double exact = u_max * u_max / 4;  // mean of (U sin ky)^2 / 2
  const double drift = std::abs(e_end / e_half - 1);
  if (rank == 0)
    fmt::print(
        "stability {}: {} steps, dt {:.4g}..{:.4g} s (sigma = {}), t = {:.1f} s, E/E_exact "
        "{:.6f}, drift over the second half {:.3e}, max |div v| h/U {:.3e}\n",
        label, result.summary.steps, dt_min, dt_max, sigma, result.summary.time, e_end / exact,
        drift, div_number);
  finite = finite && result.summary.steps == steps;
  report.add(label + ": steps completed with finite energy", finite ? steps : 0, steps, 0);
  // Steady energy within issue 21's 5 % (target 3): on the 8^3 mesh (k h = 0.79) the
  // discretisation error of the laminar profile is a few per cent (README.md).
  report.add(label + ": steady kinetic energy / exact U^2/4", e_end / exact, 1.0, 0.05);
  // Steady state reached after ~10 / (nu k^2) = 25 s; the second half only sees Poisson
  // round-off (tolerance 1e-10).
  report.add(label + ": energy drift over the second half (relative)", drift, 0, 1e-9,
             Check::at_most);
  // The approximate projection (compact Laplacian, not div grad) leaves div v ~ 3e-2 U/h
  // after the correction on tetrahedra (measured); issue 21 asks at most 0.1.
  report.add(label + ": max |div v| h / U over the run", div_number, 0, 0.1, Check::at_most);
}

void run_cases(const Context& ctx, Report& report) {
  const std::string mesh = ctx.option("mesh", "all");
  if (mesh == "all" || mesh == "split_tetra")
    run_stability(ctx, report, 0.0, "split_tetra", false, 10000);
  if (mesh == "all" || mesh == "perturbed_tetra")
    run_stability(ctx, report, 0.2, "perturbed_tetra", false, 50000);
  if (mesh == "all" || mesh == "perturbed_tetra_damped")
    run_stability(ctx, report, 0.2, "perturbed_tetra_damped", true, 10000);
}

}  // namespace

Case stability_case() {
  return {
      "stability",
      "10^5 steps at the largest admissible RK4 time step, forced flow on perturbed tetrahedra",
      run_cases,
      {CaseOption::real("sigma", "time step as a fraction of the RK4 stability estimate (1)", 0.01,
                        1.0),
       CaseOption::choice("mesh", "which runs (all)",
                          {"all", "split_tetra", "perturbed_tetra", "perturbed_tetra_damped"})}};
}

}  // namespace valsalva::validation
