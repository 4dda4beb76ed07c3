// Inviscid runs must not gain energy (issue 21, target 2): the 2D Taylor-Green vortex on 20 %
// perturbed tetrahedra, a random divergence-free field (random_solenoidal.hpp) in a periodic box
// of 20 % perturbed tetrahedra, and one that vanishes on the (slip) walls of a closed Gmsh
// Delaunay pipe; each inviscid, N steps at CFL 0.5 (full 10^4, quick 10^3), then again at CFL 0.25
// to the same time. Every run is a scene through run::Simulation (taylor_green.toml,
// random_box.toml, random_pipe.toml). Asserted per flow: the kinetic energy never above its
// initial value beyond round-off, at both steps, and (periodic flows) that the energy lost in
// the first 100 steps falls at least linearly with dt. Measured numbers: README.md.
// CSV: energy.csv (E/E0 - 1 every 10th step of every run), summary.csv.
#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "flow/run_diagnostics.hpp"
#include "validation/case.hpp"
#include "validation/inviscid_energy/random_solenoidal.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

struct Flow {
  std::string key;  // the case option's word
  std::string label;
  std::filesystem::path scene;
  std::vector<std::string> overrides;
  RandomSolenoidalSpec start;  // velocity 0: the scene's own initial.type
};

struct EnergyRun {
  double gain = 0;      // max over the steps of E/E0 - 1
  double loss_end = 0;  // 1 - E/E0 at the end
  double time = 0;
  std::int64_t steps = 0;
  std::vector<double> times, losses;  // 1 - E/E0 after every step

  // 1 - E/E0 at time t, linear between the steps.
  double loss_at(double t) const {
    const auto it = std::lower_bound(times.begin(), times.end(), t);
    if (it == times.begin()) return losses.front();
    if (it == times.end()) return losses.back();
    const auto i = static_cast<std::size_t>(it - times.begin());
    const double w = (t - times[i - 1]) / (times[i] - times[i - 1]);
    return (1 - w) * losses[i - 1] + w * losses[i];
  }
};

std::vector<Flow> flows() {
  Flow tgv{"taylor_green",
           "taylor_green perturbed_tetra",
           case_scene("taylor_green", "taylor_green.toml"),
           {"mesh.box.cell_type=tetra", "mesh.box.perturbation=0.2", "flow.viscosity=0",
            "time.dt=0", "time.cfl=0.5", "poisson.tolerance=1e-12"},
           {}};
  tgv.start.velocity = 0;
  Flow box{"random_box",
           "random perturbed_tetra box",
           case_scene("inviscid_energy", "random_box.toml"),
           {},
           {}};
  Flow pipe{
      "random_pipe", "random gmsh pipe", case_scene("inviscid_energy", "random_pipe.toml"), {}, {}};
  pipe.start.period = {1.0, 1.0, 2.0};  // 2 R, 2 R, the length
  pipe.start.pipe_radius = 0.5;
  pipe.start.pipe_length = 2.0;
  return {tgv, box, pipe};
}

EnergyRun run_energy(const Context& ctx, const Flow& flow, double cfl, std::int64_t max_steps,
                     double t_end, fmt::ostream* csv) {
  EnergyRun r;
  double e0 = 0;
  SceneRun measure;
  if (flow.start.velocity > 0) measure.initial_velocity = RandomSolenoidal(flow.start);
  auto energy = [](const run::Simulation& sim) {  // only E / E0 is used: any density will do
    return flow::kinetic_energy(sim.local(), 1.0, sim.state().velocity);
  };
  measure.at_start = [&](const run::Simulation& sim) { e0 = energy(sim); };
  measure.observer = [&](const run::Simulation& sim, std::int64_t s) {
    const double change = energy(sim) / e0 - 1;
    r.gain = std::max(r.gain, change);
    r.loss_end = -change;
    r.times.push_back(sim.state().time);
    r.losses.push_back(-change);
    if (csv && s % 10 == 0)
      csv->print("{},{},{},{:.9g},{:.9e}\n", flow.label, cfl, s, sim.state().time, change);
  };
  auto overrides = flow.overrides;
  overrides.push_back(fmt::format("time.cfl={}", cfl));
  overrides.push_back(fmt::format("time.max_steps={}", max_steps));
  overrides.push_back(fmt::format("time.end={:.17g}", t_end));
  const auto label = fmt::format("{}_cfl{}", flow.label, cfl);
  std::string dir;
  for (char c : label) dir += c == ' ' || c == '.' ? '_' : c;
  const auto result =
      run_scene_file(flow.scene, overrides, ctx.out_dir / "runs" / dir, ctx.comm, measure);
  r.time = result.summary.time;
  r.steps = result.summary.steps;
  return r;
}

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::unique_ptr<fmt::ostream> energy, summary;
  if (rank == 0) {
    energy =
        std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "energy.csv").string()));
    energy->print("flow,cfl,step,time,relative_energy_change\n");
    summary =
        std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "summary.csv").string()));
    summary->print("flow,cfl,steps,time,max_gain,loss_at_end\n");
  }
  const std::int64_t steps = ctx.quick ? 1000 : 10000;
  const std::string only = ctx.option("flow", "all");
  for (auto flow : flows()) {
    flow.start.max_wavenumber = ctx.option_int("max_wavenumber", flow.start.max_wavenumber);
    if (flow.key == "random_pipe" && !ctx.option("pipe_size").empty())
      flow.overrides.push_back("mesh.pipe.size=" + ctx.option("pipe_size"));
    if (!ctx.option("damping").empty())
      flow.overrides.push_back("poisson.damping=" + ctx.option("damping"));
    if (only != "all" && only != flow.key) continue;
    const auto a = run_energy(ctx, flow, 0.5, steps, 1e9, energy.get());
    const auto b = run_energy(ctx, flow, 0.25, 100 * steps, a.time, energy.get());
    for (const auto* r : {&a, &b})
      if (summary)
        summary->print("{},{},{},{:.9g},{:.6e},{:.6e}\n", flow.label, r == &a ? 0.5 : 0.25,
                       r->steps, r->time, r->gain, r->loss_end);
    if (rank == 0)
      fmt::print(
          "inviscid_energy {}: {} steps to t = {:.4g}: max E/E0 - 1 {:.3e} / {:.3e} (CFL 0.5 / "
          "0.25), loss at the end {:.4e} / {:.4e}\n",
          flow.label, a.steps, a.time, a.gain, b.gain, a.loss_end, b.loss_end);
    // Round-off: each step's Poisson solve stops at a relative residual of 1e-12, and the
    // energy is summed over ~1e3-1e4 nodes; a gain by the scheme is O(dt^2) (split tetrahedra:
    // 4e-3, validation/notes/energy_stability.md), nine orders above this bound.
    report.add(flow.label + ": max E/E0 - 1 over the run, CFL 0.5", a.gain, 0, 1e-12,
               Check::at_most);
    report.add(flow.label + ": max E/E0 - 1 over the run, CFL 0.25", b.gain, 0, 1e-12,
               Check::at_most);
    // The loss against dt after the first 100 steps at CFL 0.5 (while it is small; later the
    // runs are different flows), with two more halvings of the step run to that time only. A
    // loss from the time discretisation vanishes with dt at least linearly (README.md: the
    // approximate projection's O(dt), the incremental pressure's O(dt^2), RK4's damping of the
    // grid-scale modes). The pipe's first pair is not yet in that regime (README.md), so its
    // exponent is printed there and asserted from CFL 0.25 down, like every flow's.
    const double t_early = a.times.at(std::min<std::size_t>(99, a.times.size() - 1));
    const auto c = run_energy(ctx, flow, 0.125, 100 * steps, t_early, nullptr);
    const auto d = run_energy(ctx, flow, 0.0625, 100 * steps, t_early, nullptr);
    const std::array<const EnergyRun*, 4> levels{&a, &b, &c, &d};
    const std::array<double, 4> cfl{0.5, 0.25, 0.125, 0.0625};
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
      const double coarse = levels[k]->loss_at(t_early), fine = levels[k + 1]->loss_at(t_early);
      const double exponent = std::log2(coarse / fine);
      if (rank == 0)
        fmt::print(
            "inviscid_energy {}: at t = {:.4g}, loss {:.4e} / {:.4e} at CFL {} / {}, dt "
            "exponent {:.3f}\n",
            flow.label, t_early, coarse, fine, cfl[k], cfl[k + 1], exponent);
      if (k > 0 || flow.key != "random_pipe")
        report.add(
            fmt::format("{}: dt exponent of the loss after 100 steps at CFL 0.5, CFL {} / {}",
                        flow.label, cfl[k], cfl[k + 1]),
            exponent, 1.0, 0, Check::at_least);
    }
  }
}

}  // namespace

Case inviscid_energy_case() {
  return {"inviscid_energy",
          "Inviscid runs on perturbed tetrahedra and a Gmsh pipe (Taylor-Green, random "
          "divergence-free fields), 10^4 steps at CFL 0.5: the kinetic energy never grows",
          run,
          {CaseOption::choice("flow", "which flow (all)",
                              {"all", "taylor_green", "random_box", "random_pipe"}),
           CaseOption::integer("max_wavenumber",
                               "largest wave number of the random fields per period (1)", 1, 8),
           CaseOption::real("pipe_size", "the pipe's mesh size, m (0.1)", 0.01, 0.5),
           CaseOption::choice("damping", "poisson.damping of the runs (the scenes' own)",
                              {"pressure", "increment"})}};
}

}  // namespace valsalva::validation
