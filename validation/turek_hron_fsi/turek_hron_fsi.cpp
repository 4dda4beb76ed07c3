// Turek–Hron FSI1 (steady, Re 20) and FSI3 (periodic, Re 200) (Turek & Hron 2006,
// doi:10.1007/3-540-34596-5_15; refdata/turek_hron_fsi): the elastic bar behind the rigid
// cylinder, immersed (ITBM, massless solid: rho_s = rho_f as in both cases) in a tetrahedral
// slab with the cylinder body-fitted: the scene turek_hron_fsi.toml with each run's overrides,
// run by run::Simulation like `valsalva run` (fsi_run.hpp for the set-up, plane strain and the
// force convention; each run's own log.csv and structures.csv in runs/<run>/).
// FSI1: from the developed channel profile (no inflow ramp: only the steady state is compared;
// from rest the profile would take ~12 s to be flushed through the channel at U = 0.2) to
// t = 2.5 s on three meshes (size 0.02, 0.014, 0.01 near the cylinder and the bar, markers about
// h/2 apart); steady values are averages over the last 0.75 s (fsi1_convergence.csv, one row per
// mesh); uy_A and drag asserted within 5 % of TH2006 on the finest. The coupling bound (dt ~
// 1e-4 s) makes the approach to the steady state costly: the bar's slow, lightly damped bending
// mode (period ~2.5 s at size 0.02) is not decayed by 2.5 s, so uy_A is the weakest number.
// FSI3: from rest with a 1 s ramp and a 1 mm seed bend to t = 6 s; uy_A amplitude (TH's
// definition: the last period; also the mean and spread over the periods of the last 1.5 s) and
// frequency, drag and lift mean and amplitude against TH2006 within 10 % (fsi3_series.csv,
// fsi3_summary.csv). Both use the per-step coupling (why: fsi1_level and fsi3_spec below).
// Quick: FSI1 on the coarse mesh to t = 1.4 s.
// Measured numbers, their run conditions and what they show: README.md in this folder.
// Options (`valsalva validate turek_hron_fsi --set key=value`; `--options` lists them), so that
// the default run stays within the CPU budget:
//   part=fsi1|fsi3|timing   only one of the two cases, or the cost run: 300 FSI3 steps at the
//                           coarse mesh with the per-part profile (timing.csv), no FSI1
//   fsi1_level=i            FSI1 on level i only (0, 1, 2), also the timing run's level
//   fsi1_size_near=S, fsi1_size_far=F   FSI1 on one mesh of those sizes (far default 0.04)
//   fsi1_t_end=T            FSI1 end time (default 2.5 s; quick 1.4 s)
//   fsi1_ramp=T             FSI1 from rest with the inflow ramp over T s
//   fsi3_level=i            FSI3 on level i (default 0, the coarse mesh)
//   fsi3_t_end=T            FSI3 end time (default 6 s; level 2 to 10 s is about 70 CPU minutes)
//   timing_coupling=per_step|per_stage, timing_case=FSI3|FSI1   the timing run's set-up
//   kernel=peskin4|roma3|bspline3, kernel_width=W   the IB kernel (default peskin4, 4 h)
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "validation/case.hpp"
#include "validation/turek_hron_fsi/fsi_run.hpp"
#include "validation/turek_hron_fsi/periodic_stats.hpp"

namespace valsalva::validation {

namespace {

const std::vector<FsiLevel> kLevels = {{0.02, 0.06, 5}, {0.014, 0.05, 5}, {0.01, 0.04, 5}};
const int kLastLevel = static_cast<int>(kLevels.size()) - 1;

void write_series(const Context& ctx, const std::string& file, const FsiResult& r) {
  auto out = fmt::output_file((ctx.out_dir / file).string());
  out.print("t,ux_A,uy_A,drag,lift,drag_bar,lift_bar\n");
  for (const auto& s : r.samples)
    out.print("{:.6e},{:.8e},{:.8e},{:.8e},{:.8e},{:.8e},{:.8e}\n", s.t, s.ux, s.uy, s.drag, s.lift,
              s.drag_bar, s.lift_bar);
}

void write_timing(const Context& ctx, const FsiResult& r) {
  auto out = fmt::output_file((ctx.out_dir / "timing.csv").string());
  out.print(
      "ranks,nodes,markers,steps,dt,simulated_s,wall_s,wall_per_simulated_s,"
      "cpu_per_simulated_s,locate_s,spread_s,interp_s,solid_forces_s\n");
  const double simulated = r.samples.back().t;
  out.print("{},{},{},{},{:.4e},{:.4e},{:.2f},{:.1f},{:.1f},{:.3e},{:.3e},{:.3e},{:.3e}\n", r.ranks,
            r.nodes, r.markers, r.steps, r.dt, simulated, r.loop_wall, r.loop_wall / simulated,
            r.loop_cpu / simulated, r.t_locate, r.t_spread, r.t_interp, r.t_forces);
}

// The steady values: averages over the last `window` seconds (the coarse IB state keeps a small
// jitter, the kernel width jumping with the nearest fluid node), and the spread (max - min) of
// the drag over that window relative to its mean.
struct Steady {
  double ux = 0, uy = 0, drag = 0, lift = 0, drag_spread = 0;
};

Steady steady_values(const FsiResult& r, double window) {
  Steady s;
  const double t0 = r.samples.back().t - window;
  double lo = 1e300, hi = -1e300;
  int n = 0;
  for (const auto& x : r.samples) {
    if (x.t < t0) continue;
    s.ux += x.ux;
    s.uy += x.uy;
    s.drag += x.drag;
    s.lift += x.lift;
    lo = std::min(lo, x.drag);
    hi = std::max(hi, x.drag);
    ++n;
  }
  s.ux /= n;
  s.uy /= n;
  s.drag /= n;
  s.lift /= n;
  s.drag_spread = (hi - lo) / s.drag;
  return s;
}

// kernel=NAME, kernel_width=W: the IB kernel of every run (default peskin4 at 4 h, the scene's).
void kernel_option(const Context& ctx, FsiSpec& s) {
  s.kernel = ctx.option("kernel", "peskin4");
  s.kernel_width = ctx.option_real("kernel_width", 4.0);
}

FsiResult fsi1_level(const Context& ctx, const FsiLevel& level, double t_end, int number) {
  FsiSpec s;
  kernel_option(ctx, s);
  s.p = read_turek_hron_parameters(ctx.refdata_dir / "turek_hron_fsi", "FSI1");
  s.level = level;
  s.t_end = t_end;
  // From the developed profile by default; fsi1_ramp=T: from rest with the benchmark's inflow
  // ramp over T s (the start-up's effect on the steady bar).
  s.ramp = ctx.option_real("fsi1_ramp", 0.0);
  s.steady_window = 0.5;  // progress report only (tolerance 0: never stops early)
  s.steady_tolerance = 0;
  s.sample_interval = 0.005;
  s.per_step = true;  // the steady state does not depend on the coupling's time scheme
  return run_fsi(ctx, s, fmt::format("fsi1_level{}", number));
}

FsiSpec fsi3_spec(const Context& ctx, const FsiLevel& level, double t_end) {
  FsiSpec s;
  kernel_option(ctx, s);
  s.p = read_turek_hron_parameters(ctx.refdata_dir / "turek_hron_fsi", "FSI3");
  s.level = level;
  s.t_end = t_end;
  s.ramp = 1;  // half the benchmark's: only the periodic state is compared
  s.initial_bend = 1e-3;
  s.sample_interval = 1e-3;
  // Lagging the force by one step costs a phase error omega dt ~ 3e-3 rad per step at 5 Hz
  // and dt ~ 1e-4 s, for 1.4x fewer marker locations per simulated second than per-stage.
  s.per_step = true;
  return s;
}

// The FSI1 meshes to run, numbered as in the table (1..3): fsi1_level=i level i only (0-based);
// fsi1_size_near=S (fsi1_size_far=F) one mesh of those sizes instead, numbered 4; quick: level 1.
struct NumberedLevel {
  int number;
  FsiLevel level;
};

std::vector<NumberedLevel> fsi1_levels(const Context& ctx) {
  if (!ctx.option("fsi1_size_near").empty()) {
    const FsiLevel own{ctx.option_real("fsi1_size_near", 0.01),
                       ctx.option_real("fsi1_size_far", 0.04), kLevels.back().layers};
    if (own.size_far < own.size_near)
      throw std::invalid_argument(
          fmt::format("turek_hron_fsi: fsi1_size_far = {} is below fsi1_size_near = {}",
                      own.size_far, own.size_near));
    return {{kLastLevel + 2, own}};
  }
  if (ctx.quick) return {{1, kLevels[0]}};
  const int only = ctx.option_int("fsi1_level", -1);
  std::vector<NumberedLevel> out;
  for (int l = 0; l <= kLastLevel; ++l)
    if (only < 0 || l == only) out.push_back({l + 1, kLevels[l]});
  return out;
}

void run_fsi1(const Context& ctx, Report& report, int rank) {
  const auto dir = ctx.refdata_dir / "turek_hron_fsi";
  const auto ref = [&](const char* q) {
    return read_turek_hron_reference(dir, "FSI1", q, "TH2006").mean;
  };
  const double u_bar = read_turek_hron_parameters(dir, "FSI1").U_bar;
  const double ux_ref = ref("ux_A"), uy_ref = ref("uy_A"), drag_ref = ref("drag"),
               lift_ref = ref("lift");
  std::optional<fmt::ostream> csv;
  if (rank == 0) {
    csv.emplace(fmt::output_file((ctx.out_dir / "fsi1_convergence.csv").string()));
    csv->print(
        "size_near,size_far,nodes,markers,dt,steps,t_end,ux_A,uy_A,drag,lift,"
        "err_ux,err_uy,err_drag,err_lift,drag_spread_last_window,max_marker_w,balance_error,"
        "wall_s\n");
  }
  const auto levels = fsi1_levels(ctx);
  FsiResult r;
  Steady s;
  for (const auto& [number, level] : levels) {
    const double t_end = ctx.option_real("fsi1_t_end", ctx.quick ? 1.4 : 2.5);
    r = fsi1_level(ctx, level, t_end, number);
    s = steady_values(r, ctx.quick ? 0.3 : 0.75);
    if (rank == 0) {
      csv->print(
          "{},{},{},{},{:.4e},{},{:.3f},{:.6e},{:.6e},{:.6f},{:.6f},{:.4f},{:.4f},{:.4f},"
          "{:.4f},{:.2e},{:.2e},{:.2e},{:.1f}\n",
          level.size_near, level.size_far, r.nodes, r.markers, r.dt, r.steps, r.samples.back().t,
          s.ux, s.uy, s.drag, s.lift, s.ux / ux_ref - 1, s.uy / uy_ref - 1, s.drag / drag_ref - 1,
          s.lift / lift_ref - 1, s.drag_spread, r.max_w, r.balance_error, r.wall);
      csv->flush();
      write_series(ctx, fmt::format("fsi1_series_level{}.csv", number), r);
      fmt::print(
          "FSI1 level {} (size {}): {} nodes, {} markers, dt {:.3e}, {} steps to "
          "t = {:.2f}: ux_A {:.4e} uy_A {:.4e} drag {:.4f} lift {:.4f}, {:.0f} s\n",
          number, level.size_near, r.nodes, r.markers, r.dt, r.steps, r.samples.back().t, s.ux,
          s.uy, s.drag, s.lift, r.wall);
    }
  }
  report.add("FSI1 spread force balance |sum V f - sum F| / |sum F|", r.balance_error, 0, 1e-11,
             Check::at_most);
  if (ctx.quick) {
    // Coarse mesh (size 0.02 = the bar's thickness, kernel support 0.08) to t = 1.4 s from the
    // developed profile, drag averaged over the last 0.3 s: measured 22.30 N/m (+56 % on
    // TH2006: the 4h kernel blocks the channel like a bar several times thicker; the finer
    // meshes come down to +27 % and +22 %). The coarse mesh's own plateau, averaged over
    // t = 1.75..2.5 s of the 2.5 s run, is 21.54 N/m (it stays within 21.3..21.7 up to 6 s):
    // the quick value is checked against it within 10 % (a regression of the coupling, the
    // force balance or the start-up shows) and against TH2006 within 70 %. The marker
    // z-velocity (plane strain) measured 0.84 % of the peak inflow velocity.
    report.add("FSI1 quick drag [N/m] vs the coarse mesh's plateau 21.54 (2.5 s run), 10 %", s.drag,
               21.54, 0.1 * 21.54);
    report.add("FSI1 quick drag [N/m], coarse mesh, within 70 % of TH2006", s.drag, drag_ref,
               0.7 * drag_ref);
    report.add("FSI1 quick max marker |w| / U_max (plane strain)", r.max_w / (1.5 * u_bar), 0, 0.02,
               Check::at_most);
    return;
  }
  report.add(fmt::format("FSI1 uy_A [m], size {}", levels.back().level.size_near), s.uy, uy_ref,
             0.05 * uy_ref);
  report.add(fmt::format("FSI1 drag [N/m], size {}", levels.back().level.size_near), s.drag,
             drag_ref, 0.05 * drag_ref);
  report.add("FSI1 steady: drag (max - min) / mean over the last 0.75 s", s.drag_spread, 0, 0.01,
             Check::at_most);
}

// Time average of y over t >= t_from (uniform samples).
double time_mean(const std::vector<double>& t, const std::vector<double>& y, double t_from) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_from) {
      sum += y[i];
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

void run_fsi3(const Context& ctx, Report& report, int rank) {
  const auto dir = ctx.refdata_dir / "turek_hron_fsi";
  const int level = ctx.option_int("fsi3_level", 0);
  const auto spec = fsi3_spec(ctx, kLevels[level], ctx.option_real("fsi3_t_end", 6.0));
  const auto r = run_fsi(ctx, spec, "fsi3");
  std::vector<double> t, uy, drag, lift;
  for (const auto& s : r.samples) {
    t.push_back(s.t);
    uy.push_back(s.uy);
    drag.push_back(s.drag);
    lift.push_back(s.lift);
  }
  // The last 1.5 s: several periods of the established oscillation.
  const auto y = periodic_stats(t, uy, spec.t_end - 1.5);
  const auto d = window_stats(t, drag, y.t0, y.t1), l = window_stats(t, lift, y.t0, y.t1);
  if (rank == 0) {
    write_series(ctx, "fsi3_series.csv", r);
    auto out = fmt::output_file((ctx.out_dir / "fsi3_summary.csv").string());
    out.print(
        "size_near,nodes,markers,dt,steps,t_end,periods,uy_mean,uy_amplitude,"
        "uy_amplitude_period_mean,uy_amplitude_period_std,frequency,drag_mean,"
        "drag_amplitude,drag_time_mean,lift_mean,lift_amplitude,wall_s,wall_per_simulated_s,"
        "cpu_per_simulated_s\n");
    out.print(
        "{},{},{},{:.4e},{},{:.3f},{},{:.5e},{:.5e},{:.5e},{:.5e},{:.4f},{:.4f},{:.4f},{:.4f},"
        "{:.4f},{:.4f},{:.1f},{:.1f},{:.1f}\n",
        spec.level.size_near, r.nodes, r.markers, r.dt, r.steps, r.samples.back().t, y.periods,
        y.mean, y.amplitude, y.amplitude_mean, y.amplitude_std, y.frequency, d.mean, d.amplitude,
        time_mean(t, drag, spec.t_end - 1.5), l.mean, l.amplitude, r.wall,
        r.loop_wall / r.samples.back().t, r.loop_cpu / r.samples.back().t);
    fmt::print(
        "FSI3 (size {}): {} steps, dt {:.3e}: uy_A {:.4e} +- {:.4e} at {:.3f} Hz ({} periods), "
        "drag {:.2f} +- {:.2f}, lift {:.2f} +- {:.2f}; {:.0f} s\n",
        spec.level.size_near, r.steps, r.dt, y.mean, y.amplitude, y.frequency, y.periods, d.mean,
        d.amplitude, l.mean, l.amplitude, r.wall);
  }
  const auto uy_ref = read_turek_hron_reference(dir, "FSI3", "uy_A", "TH2006");
  const auto drag_ref = read_turek_hron_reference(dir, "FSI3", "drag", "TH2006");
  const auto lift_ref = read_turek_hron_reference(dir, "FSI3", "lift", "TH2006");
  const auto size = fmt::format("size {}", spec.level.size_near);
  report.add("FSI3 uy_A amplitude [m], " + size, y.amplitude, uy_ref.amplitude,
             0.1 * uy_ref.amplitude);
  report.add("FSI3 uy_A amplitude [m], mean over the periods of the last 1.5 s, " + size,
             y.amplitude_mean, uy_ref.amplitude, 0.1 * uy_ref.amplitude);
  report.add("FSI3 uy_A frequency [Hz], " + size, y.frequency, uy_ref.frequency,
             0.1 * uy_ref.frequency);
  report.add("FSI3 drag mean [N/m], " + size, d.mean, drag_ref.mean, 0.1 * drag_ref.mean);
  report.add("FSI3 drag amplitude [N/m], " + size, d.amplitude, drag_ref.amplitude,
             0.1 * drag_ref.amplitude);
  report.add("FSI3 lift amplitude [N/m], " + size, l.amplitude, lift_ref.amplitude,
             0.1 * lift_ref.amplitude);
}

void run_timing(const Context& ctx, Report& report, int rank) {
  auto spec = fsi3_spec(ctx, kLevels[0], 10.0);
  spec.max_steps = 300;
  spec.ramp = 0;  // full speed from the start: the cost of the periodic state
  spec.profile = true;
  spec.per_step = ctx.option("timing_coupling", "per_step") == "per_step";
  spec.level = kLevels[ctx.option_int("fsi1_level", 0)];
  if (ctx.option("timing_case") == "FSI1")
    spec.p = read_turek_hron_parameters(ctx.refdata_dir / "turek_hron_fsi", "FSI1");
  const auto r = run_fsi(ctx, spec, "timing");
  // The cost is the result; the one check is the spreading's force balance.
  report.add("FSI3 timing run: spread force balance |sum V f - sum F| / |sum F|", r.balance_error,
             0, 1e-11, Check::at_most);
  if (rank == 0) {
    write_timing(ctx, r);
    fmt::print(
        "FSI3 timing: {} ranks, {} nodes, {} markers, {} steps of {:.3e} s in {:.1f} s: {:.0f} s "
        "per simulated second (CPU {:.0f} s); per call locate {:.2e} s, spread {:.2e} s, "
        "interpolate {:.2e} s, solid forces {:.2e} s\n",
        r.ranks, r.nodes, r.markers, r.steps, r.dt, r.wall, r.loop_wall / r.samples.back().t,
        r.loop_cpu / r.samples.back().t, r.t_locate, r.t_spread, r.t_interp, r.t_forces);
  }
}

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const std::string only = ctx.option("part");
  if (only == "timing") return run_timing(ctx, report, rank);
  if (only != "fsi3") run_fsi1(ctx, report, rank);
  if (!ctx.quick && only != "fsi1") run_fsi3(ctx, report, rank);
}

}  // namespace

Case turek_hron_fsi_case() {
  return {
      "turek_hron_fsi",
      "Turek-Hron FSI1 (steady) and FSI3 (periodic): immersed elastic bar behind a "
      "body-fitted cylinder, tip displacement, drag, lift vs TH2006",
      run,
      {CaseOption::choice("part",
                          "one case only, or 300 FSI3 steps with the cost profile (default: "
                          "both cases)",
                          {"fsi1", "fsi3", "timing"}),
       CaseOption::integer("fsi1_level",
                           "FSI1 on that mesh only (default: all three); also the timing "
                           "run's mesh (default 0)",
                           0, kLastLevel),
       CaseOption::real("fsi1_size_near",
                        "FSI1 on one mesh of this size near the cylinder and the bar, m (instead "
                        "of the levels)",
                        2e-3, 0.05),
       CaseOption::real("fsi1_size_far",
                        "with fsi1_size_near: the far-field size, m (default 0.04)", 2e-3, 0.1),
       CaseOption::real("fsi1_t_end", "FSI1 end time in s (default 2.5; quick 1.4)", 0.01, 1000),
       CaseOption::real("fsi1_ramp",
                        "FSI1 from rest with the inflow ramped over that many s (default 0: "
                        "from the developed profile)",
                        0, 100),
       CaseOption::integer("fsi3_level", "FSI3 mesh (default 0)", 0, kLastLevel),
       CaseOption::real("fsi3_t_end", "FSI3 end time in s (default 6)", 0.01, 1000),
       CaseOption::choice("timing_coupling", "the timing run's coupling (default per_step)",
                          {"per_step", "per_stage"}),
       CaseOption::choice("timing_case", "the timing run's parameters (default FSI3)",
                          {"FSI1", "FSI3"}),
       CaseOption::choice("kernel", "IB base kernel of every run (default peskin4)",
                          {"peskin4", "roma3", "bspline3"}),
       // The slab is 5 layers of size_near deep: a wider support would overlap its own periodic
       // image in z.
       CaseOption::real("kernel_width", "IB kernel support width in local mesh sizes (default 4)",
                        2, 4.5)}};
}

}  // namespace valsalva::validation
