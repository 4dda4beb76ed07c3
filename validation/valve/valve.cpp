// The reference pulse-duplicator valve (issue 18; ../shared/design/valve_case.md) as users run
// it: the shipped scenes/valve_quick.toml (quick level, shortened to the start of the forward
// flow) and scenes/valve_m1.toml (full level, `cycles` cardiac cycles) through run::Simulation,
// on the meshes scripts/make-valve-quick and scripts/make-valve-m1 write. The metrics read the
// run's valve.csv, so the same evaluation applies to a run made by `valsalva run` in restarted
// pieces (`--set from_run=DIR`):
//   mass: |inlet - outlet flow| against the waveform's peak (the leaflets move no volume);
//   the imposed flow: the inlet flow against the table (scenes/data/valve_flow_rate.csv);
//   every sample's TPG, opening ratio and stress finite;
//   full level, over the cycles after the first two: TPG_max within 20 % of the experiment's
//   5.28 mmHg and repeating within 10 %; leakage volume below 1 % of the stroke volume; the
//   opening start, fully-open and closing instants within 0.05 s of t1, t2 and t6. Per-cycle
//   indices (analysis/valve_cycles.hpp, recomputed from valve.csv) go to cycles.csv.
#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>

#include "analysis/valve_cycles.hpp"
#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "io/waveform_table.hpp"
#include "run/data_dir.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

namespace fs = std::filesystem;

// The study's instants (valve_case.md): opening t1, early systole t2 (fully open), closing t6.
constexpr double kT1 = 0.15, kT2 = 0.20, kT6 = 0.80;
constexpr double kTpgMaxExperiment = 5.28;  // mmHg
constexpr double kPeriod = 1.0;             // s, of scenes/data/valve_flow_rate.csv
constexpr double kQuickEnd = 0.13;          // s: the forward flow is 0.03 s old
constexpr int kSettling = 2;                // cycles left out of the statistics

// Both mesh scripts write geom/root.msh (and geom/leaflets.msh) and closed.msh.
constexpr const char* kRootMesh = "geom/root.msh";

struct Level {
  std::string scene;   // in scenes/
  fs::path meshes;     // folder of the generated meshes
  std::string script;  // what makes them
};

Level level(const Context& ctx) {
  const fs::path data = run::data_dir();
  Level l = ctx.quick ? Level{"valve_quick.toml", data / "runs" / "valve_quick",
                              "scripts/make-valve-quick"}
                      : Level{"valve_m1.toml", data / "runs" / "valve_m1", "scripts/make-valve-m1"};
  if (const auto dir = ctx.option("meshes"); !dir.empty()) l.meshes = dir;
  for (const auto& file : {kRootMesh, "closed.msh"})
    if (!fs::exists(l.meshes / file))
      throw std::runtime_error(fmt::format(
          "valve: {} is missing: make the meshes with `{} build/bin/valsalva {}` from the "
          "source tree (or give another folder with --set meshes=DIR)",
          (l.meshes / file).string(), l.script, l.meshes.string()));
  return l;
}

// The run's valve.csv: its own run, or one made elsewhere (restarted pieces of a long run).
fs::path run_valve(const Context& ctx) {
  if (const auto from = ctx.option("from_run"); !from.empty()) return from;
  const Level l = level(ctx);
  const fs::path dir = ctx.out_dir / "run";
  std::vector<std::string> overrides{
      fmt::format("mesh.file=\"{}\"", fs::absolute(l.meshes / kRootMesh).string()),
      fmt::format("structure.valve.file=\"{}\"", fs::absolute(l.meshes / "closed.msh").string())};
  overrides.push_back(ctx.quick
                          ? fmt::format("time.end={}", kQuickEnd)
                          : fmt::format("time.end={}", kPeriod * ctx.option_int("cycles", 12)));
  run_scene_file(run::data_dir() / "scenes" / l.scene, overrides, dir, ctx.comm);
  return dir;
}

struct Samples {
  std::vector<double> time, inflow, outflow;
  std::vector<analysis::ValveSample> valve;
  int non_finite = 0;
};

Samples read_valve_csv(const fs::path& file) {
  core::TableFormat format;
  format.header = core::TableHeader::required;
  // nan: no contact pair within the contact search distance (valve/valve_monitor.cpp).
  format.maskable = [](const std::string& column) { return column == "min_gap"; };
  const auto table = core::read_numeric_table(file, format);
  Samples s{table.column("time"), table.column("inlet_flow"), table.column("outlet_flow"), {}, 0};
  const auto tpg = table.column("tpg_mmHg"), ratio = table.column("opening_ratio"),
             stress = table.column("max_von_mises");
  for (std::size_t i = 0; i < s.time.size(); ++i) {
    s.valve.push_back({s.time[i], s.inflow[i], tpg[i], ratio[i], stress[i]});
    if (!std::isfinite(tpg[i]) || !std::isfinite(ratio[i]) || !std::isfinite(stress[i]))
      ++s.non_finite;
  }
  return s;
}

// Cycles the samples cover completely (a sample within 1 % of the period of both ends).
std::vector<analysis::CycleSummary> complete_cycles(const Samples& s) {
  std::vector<analysis::CycleSummary> out;
  if (s.time.empty()) return out;
  const analysis::CycleOptions options{kPeriod, 0, 0.05, 0.9};
  for (int c = 0; (c + 1) * kPeriod <= s.time.back() + 0.01 * kPeriod; ++c) {
    std::vector<analysis::ValveSample> cycle;
    for (const auto& v : s.valve)
      if (v.time >= c * kPeriod && v.time <= (c + 1) * kPeriod) cycle.push_back(v);
    if (cycle.size() < 2 || cycle.front().time > (c + 0.01) * kPeriod) continue;
    out.push_back(analysis::summarise_cycle(c, cycle, options));
  }
  return out;
}

void write_cycles(const fs::path& file, const std::vector<analysis::CycleSummary>& cycles) {
  auto out = fmt::output_file(file.string());
  out.print(
      "cycle,tpg_max_mmHg,tpg_min_mmHg,forward_volume_m3,closing_volume_m3,leakage_volume_m3,"
      "min_opening_ratio,max_opening_ratio,opening_start_s,fully_open_s,closing_s\n");
  for (const auto& c : cycles)
    out.print("{},{:.6g},{:.6g},{:.6e},{:.6e},{:.6e},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", c.cycle,
              c.tpg_max, c.tpg_min, c.forward_volume, c.closing_volume, c.leakage_volume,
              c.min_opening_ratio, c.max_opening_ratio, c.opening_start, c.fully_open, c.closing);
}

double mean(const std::vector<analysis::CycleSummary>& cycles,
            double analysis::CycleSummary::*field) {
  double sum = 0;
  for (const auto& c : cycles) sum += c.*field;
  return cycles.empty() ? std::nan("") : sum / double(cycles.size());
}

void cycle_metrics(const Context& ctx, const std::vector<analysis::CycleSummary>& all,
                   Report& report) {
  const int wanted = ctx.option_int("cycles", 12);
  report.add("complete cycles", double(all.size()), wanted, 0, Check::at_least);
  const std::vector<analysis::CycleSummary> settled(
      all.begin() + std::min<std::ptrdiff_t>(kSettling, std::ssize(all)), all.end());
  using S = analysis::CycleSummary;
  const double tpg = mean(settled, &S::tpg_max);
  report.add("TPG_max (mmHg), mean over the cycles after the first two", tpg, kTpgMaxExperiment,
             0.2 * kTpgMaxExperiment);
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& c : settled) lo = std::min(lo, c.tpg_max), hi = std::max(hi, c.tpg_max);
  report.add("TPG_max cycle-to-cycle spread, (max - min) / mean", (hi - lo) / tpg, 0, 0.1,
             Check::at_most);
  report.add("leakage volume / stroke volume",
             mean(settled, &S::leakage_volume) / mean(settled, &S::forward_volume), 0, 0.01,
             Check::at_most);
  report.add("opening start (s)", mean(settled, &S::opening_start), kT1, 0.05);
  report.add("fully open (s)", mean(settled, &S::fully_open), kT2, 0.05);
  report.add("closing (s)", mean(settled, &S::closing), kT6, 0.05);
}

void run_case(const Context& ctx, Report& report) {
  const fs::path dir = run_valve(ctx);
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  double values[5] = {};  // mass, table, non-finite, samples, peak
  std::vector<analysis::CycleSummary> cycles;
  if (rank == 0) {
    const Samples s = read_valve_csv(dir / "valve.csv");
    const auto table =
        io::read_waveform_table(run::data_dir() / "scenes" / "data" / "valve_flow_rate.csv");
    double peak = 0, mass = 0, imposed = 0;
    for (double q : table.q) peak = std::max(peak, std::abs(q));
    for (std::size_t i = 0; i < s.time.size(); ++i) {
      mass = std::max(mass, std::abs(s.inflow[i] - s.outflow[i]));
      imposed = std::max(imposed, std::abs(s.inflow[i] - table(s.time[i])));
    }
    values[0] = mass / peak, values[1] = imposed / peak, values[2] = s.non_finite;
    values[3] = double(s.time.size()), values[4] = peak;
    cycles = complete_cycles(s);
    write_cycles(ctx.out_dir / "cycles.csv", cycles);
  }
  core::Comm(ctx.comm).broadcast(std::span<double>(values, 5));
  // The imbalance is the Poisson tolerance's (1e-8 relative) on a flux of the peak's order.
  report.add("max |inlet - outlet flow| / peak flow", values[0], 0, 1e-6, Check::at_most);
  // The inlet interpolates the same table linearly: round-off only.
  report.add("max |inlet flow - table| / peak flow", values[1], 0, 1e-9, Check::at_most);
  report.add("samples with a non-finite TPG, opening ratio or stress", values[2], 0, 0);
  report.add("valve.csv samples", values[3], ctx.quick ? 50 : 1000, 0, Check::at_least);
  if (ctx.quick && ctx.option("from_run").empty()) return;
  int count = static_cast<int>(cycles.size());
  core::Comm(ctx.comm).broadcast(count);
  if (rank != 0) cycles.resize(static_cast<std::size_t>(count));
  VALSALVA_MPI(MPI_Bcast(cycles.data(), count * static_cast<int>(sizeof(analysis::CycleSummary)),
                         MPI_BYTE, 0, ctx.comm));
  cycle_metrics(ctx, cycles, report);
}

}  // namespace

Case valve_case() {
  return {"valve",
          "The reference pulse-duplicator valve as users run it (scenes/valve_quick.toml to "
          "t = 0.13 s quick, scenes/valve_m1.toml for `cycles` cycles full): mass, the imposed "
          "flow, and per cycle TPG_max, leakage and the opening and closing instants against "
          "the study's",
          run_case,
          {CaseOption::integer("cycles", "full level: cardiac cycles to run (default 12)", 3, 48),
           CaseOption::directory("meshes",
                                 "folder of the level's meshes (default runs/valve_quick or "
                                 "runs/valve_m1 of the source tree)"),
           CaseOption::directory("from_run",
                                 "evaluate the valve.csv of an existing run of the level's "
                                 "scene instead of running it (e.g. a long run in pieces)")}};
}

}  // namespace valsalva::validation
