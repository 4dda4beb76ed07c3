// Lid-driven cavity (flow-solver issue, verification 4), Re = 100 and Re = 1000: unit square, lid
// y = 1 moving at U = 1 in +x (wall velocity), the other three sides no-slip, a periodic slab of 3
// hexahedral cells in z, uniform mesh (io/box_generator has no wall stretching). Each level runs
// to steady state, the coarsest from rest and every finer one from the previous level's steady
// field interpolated bilinearly (only the time to get there depends on the start: Re 100 at 96^2
// takes t = 3.3, 24^2 from rest t = 13.5). Each level is validation/cavity/cavity.toml with the
// level's overrides, run by run::Simulation (`valsalva run`'s path). Time step: 0.8 of the RK4
// stability limit of flow::stability_rates (time.stability_fraction, every step; viscous-limited at
// Re 100, dt ~ h^2 / nu; convection and viscosity both count at Re 1000). Steady: max_j |u_j^{n+1}
// - u_j^n| / dt below 1e-4 U^2/L (quick 1e-3); the measured decay rate of that rate near the end
// (Re 100: ~1 /s; Re 1000: 0.07, 0.13, 0.26 /s at 32^2, 64^2, 128^2) puts the remaining distance to
// the steady state at 1e-4 U (Re 100) and 1.4e-3, 8e-4, 4e-4 U (Re 1000). The centreline profiles
// u(y) at x = 1/2 and v(x) at y = 1/2 (N even: nodal lines) are interpolated linearly at the points
// of U. Ghia, K.N. Ghia, C.T. Shin, J. Comput. Phys. 48 (1982) 387-411 (129^2 multigrid, stream
// function-vorticity; validation/refdata/ ghia1982_cavity; of the typos its SOURCE.txt names, v(Re
// 1000, x = 0.5) is checked to be the consensus 0.02526, Re 3200 is not used). Corner nodes belong
// to the side walls (a stationary wall wins over the moving lid), as in Ghia's discretisation where
// the lid velocity starts inside the corners. Metric: max over both lines of |u - u_Ghia| / U on
// the finest level, the target 1 %; plus the h -> 0 Richardson estimate of the two finest
// levels (order 2).
//
// Measured numbers, their run conditions and what they show: README.md in this folder.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "run/simulation.hpp"
#include "scene/scene.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

struct Profile {
  std::vector<double> s, value;  // position along the line, velocity component
};

// Column `re_column` ("Re100") of a Ghia table against its first column (y or x), read by the
// strict table reader (header of names, '#' comments).
Profile read_ghia(const std::filesystem::path& file, const std::string& re_column) {
  const auto table = core::read_numeric_table(file, core::TableHeader::required);
  Profile p;
  p.value = table.column(re_column);
  for (const auto& row : table.rows) p.s.push_back(row[0]);
  return p;
}

// Linear interpolation of a profile given at uniformly spaced nodes s_k = k / n.
double interpolate(const std::vector<double>& nodal, double s) {
  const int n = static_cast<int>(nodal.size()) - 1;
  const int k = std::clamp(static_cast<int>(std::floor(s * n)), 0, n - 1);
  const double w = s * n - k;
  return (1 - w) * nodal[k] + w * nodal[k + 1];
}

// Nodal field on the z = 0 layer of an N^2 level, (N + 1)^2 values, index iy (N + 1) + ix.
struct PlaneField {
  int n = 0;
  std::vector<double> u, v;
  // Bilinear interpolation at (x, y) in the unit square.
  Eigen::Vector2d at(double x, double y) const {
    const int i = std::clamp(static_cast<int>(std::floor(x * n)), 0, n - 1);
    const int j = std::clamp(static_cast<int>(std::floor(y * n)), 0, n - 1);
    const double a = x * n - i, b = y * n - j;
    const auto f = [&](const std::vector<double>& g) {
      const auto g_at = [&](int di, int dj) { return g[(j + dj) * (n + 1) + i + di]; };
      return (1 - a) * (1 - b) * g_at(0, 0) + a * (1 - b) * g_at(1, 0) + (1 - a) * b * g_at(0, 1) +
             a * b * g_at(1, 1);
    };
    return {f(u), f(v)};
  }
};

struct LevelResult {
  int cells = 0, steps = 0;
  double time = 0, wall = 0, dev_u = 0, dev_v = 0, change = 0;
  double diff_to_coarser = 0;   // max over Ghia's points of |profile - coarser level's profile|
  std::vector<double> at_ghia;  // computed u then v at Ghia's points
  PlaneField plane;             // the steady field, initial state of the next level
};

// One mesh level at Reynolds number `re`: from rest, or from the steady field of a coarser level
// (`start`, interpolated bilinearly; only the time to reach the steady state depends on it), until
// max |du/dt| < tolerance U^2/L or t = t_max.
LevelResult run_level(const Context& ctx, int n, double re, double tolerance, double t_max,
                      const Profile& ghia_u, const Profile& ghia_v, const PlaneField* start) {
  const double lid = 1.0;
  const auto tag = fmt::format("Re{:g}_N{}", re, n);
  LevelResult r;
  r.cells = n;
  const auto start_clock = std::chrono::steady_clock::now();
  // The scene's run (validation/cavity/cavity.toml), kept until the profiles are read from its
  // final state; its log.csv is in runs/<tag>/.
  const auto scene =
      scene::load_scene(case_scene("cavity", "cavity.toml"),
                        {fmt::format("mesh.box.cells=[{}, {}, 3]", n, n),
                         fmt::format("mesh.box.length=[1.0, 1.0, {:.17g}]", 3.0 / n),
                         fmt::format("flow.viscosity={:.17g}", lid * 1.0 / re),
                         fmt::format("time.steady_tolerance={:.17g}", tolerance * lid * lid),
                         fmt::format("time.end={:.17g}", t_max)});
  run::Simulation sim(scene, level_request(ctx.out_dir / "runs" / tag), ctx.comm);
  if (start)
    sim.set_initial_velocity([&](const Eigen::Vector3d& x) {
      const auto uv = start->at(x.x(), x.y());
      return Eigen::Vector3d(uv.x(), uv.y(), 0);
    });
  const auto result = sim.run();
  const auto& local = sim.local();
  const auto& state = sim.state();
  r.steps = static_cast<int>(result.summary.steps);
  r.change = result.summary.change_rate;
  r.time = state.time;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_clock).count();

  // The z = 0 node layer; owned nodes contribute, summed over ranks.
  auto& plane = r.plane;
  plane.n = n;
  plane.u.assign((n + 1) * (n + 1), 0.0);
  plane.v.assign((n + 1) * (n + 1), 0.0);
  const double h = 1.0 / n, eps = 1e-6 * h;
  for (int i = 0; i < local.num_owned; ++i) {
    const auto& x = local.position[i];
    if (std::abs(x.z()) > eps) continue;
    const int k = static_cast<int>(std::lround(x.y() / h)) * (n + 1) +
                  static_cast<int>(std::lround(x.x() / h));
    plane.u[k] = state.velocity[i].x();
    plane.v[k] = state.velocity[i].y();
  }
  for (auto* f : {&plane.u, &plane.v}) core::Comm(ctx.comm).sum_in_place(*f);
  // Centreline profiles (N even: x = 1/2 and y = 1/2 are node lines).
  std::vector<double> u_line(n + 1), v_line(n + 1);
  for (int k = 0; k <= n; ++k) {
    u_line[k] = plane.u[k * (n + 1) + n / 2];
    v_line[k] = plane.v[(n / 2) * (n + 1) + k];
  }
  for (std::size_t k = 0; k < ghia_u.s.size(); ++k) {
    r.at_ghia.push_back(interpolate(u_line, ghia_u.s[k]));
    r.dev_u = std::max(r.dev_u, std::abs(r.at_ghia.back() - ghia_u.value[k]));
  }
  for (std::size_t k = 0; k < ghia_v.s.size(); ++k) {
    r.at_ghia.push_back(interpolate(v_line, ghia_v.s[k]));
    r.dev_v = std::max(r.dev_v, std::abs(r.at_ghia.back() - ghia_v.value[k]));
  }
  r.dev_u /= lid;
  r.dev_v /= lid;

  if (local.comm.root()) {
    std::ofstream out(ctx.out_dir / fmt::format("profiles_{}.csv", tag));
    out << "s,u_at_x_half,v_at_y_half\n";
    for (int k = 0; k <= n; ++k)
      out << fmt::format("{:.8f},{:.10e},{:.10e}\n", k * h, u_line[k], v_line[k]);
    fmt::print(
        "cavity Re {:g} N = {}: {} steps to t = {:.2f} (max |du/dt| {:.2e}), wall {:.1f} s, max "
        "deviation from Ghia: u {:.4f} U, v {:.4f} U\n",
        re, n, r.steps, r.time, r.change, r.wall, r.dev_u, r.dev_v);
    std::fflush(stdout);
  }
  return r;
}

// One Reynolds number on a list of levels (each started from the previous level's field).
struct ReSetup {
  double re = 100;
  std::vector<int> levels;  // successive levels twice as fine
  double tolerance = 1e-4;  // steady: max |du/dt| below tolerance U^2/L
  double t_max = 200;
  double bound = 0.01;     // max deviation from Ghia / U asserted on the finest level
  double min_order = 1.8;  // observed self-convergence order asserted with >= 3 levels
};

// Returns the levels, with `diff_to_coarser` filled in.
std::vector<LevelResult> run_re(const Context& ctx, Report& report, const ReSetup& setup) {
  const auto dir = ctx.refdata_dir / "ghia1982_cavity";
  const auto column = fmt::format("Re{:g}", setup.re);
  const auto ghia_u = read_ghia(dir / "ghia1982_u_vertical_centreline.csv", column);
  const auto ghia_v = read_ghia(dir / "ghia1982_v_horizontal_centreline.csv", column);
  // validation/refdata/ghia1982_cavity/SOURCE.txt names two typos: v(Re 1000, x = 0.5) is
  // 0.02526 (the cuIBM copy's 0.024260 is a transcription error; the CSV read here has the
  // consensus value, checked below) and u(Re 3200, y = 0.4531) = -0.86636 (not used here).
  for (std::size_t k = 0; k < ghia_v.s.size(); ++k)
    if (setup.re == 1000 && ghia_v.s[k] == 0.5 && ghia_v.value[k] != 0.02526)
      throw std::runtime_error(fmt::format(
          "cavity: Ghia v(Re 1000, x = 0.5) = {} in {}, expected 0.02526 (see SOURCE.txt)",
          ghia_v.value[k], dir.string()));
  std::vector<LevelResult> results;
  for (int n : setup.levels)
    results.push_back(run_level(ctx, n, setup.re, setup.tolerance, setup.t_max, ghia_u, ghia_v,
                                results.empty() ? nullptr : &results.back().plane));
  const std::size_t last = results.size() - 1;
  const auto& fine = results.back();
  const auto& coarse = results.front();
  // Self-convergence: D_k = max over Ghia's points of |profile_{2N} - profile_N|.
  for (std::size_t k = 1; k < results.size(); ++k)
    for (std::size_t j = 0; j < results[k].at_ghia.size(); ++j)
      results[k].diff_to_coarser = std::max(
          results[k].diff_to_coarser, std::abs(results[k].at_ghia[j] - results[k - 1].at_ghia[j]));
  // Richardson extrapolation h -> 0 of the two finest levels (order 2) at Ghia's points: where
  // the deviation from Ghia tends to (Ghia's own discretisation error), not a pass/fail metric.
  std::vector<double> extrapolated = fine.at_ghia;
  if (results.size() >= 2)
    for (std::size_t j = 0; j < extrapolated.size(); ++j)
      extrapolated[j] += (fine.at_ghia[j] - results[last - 1].at_ghia[j]) / 3;
  std::vector<std::pair<char, double>> points;  // Ghia's points, u then v, and Ghia's values
  std::vector<double> ghia;
  for (const auto* g : {&ghia_u, &ghia_v})
    for (std::size_t k = 0; k < g->s.size(); ++k) {
      points.emplace_back(g == &ghia_u ? 'u' : 'v', g->s[k]);
      ghia.push_back(g->value[k]);
    }
  double limit_dev = 0;
  for (std::size_t j = 0; j < ghia.size(); ++j)
    limit_dev = std::max(limit_dev, std::abs(extrapolated[j] - ghia[j]));
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (rank == 0) {
    // Ghia's points with the finest and the extrapolated profiles, for plot.py.
    std::ofstream out(ctx.out_dir / fmt::format("ghia_{}.csv", column));
    out << "line,s,value,finest,extrapolated\n";
    for (std::size_t j = 0; j < ghia.size(); ++j)
      out << fmt::format("{},{},{},{:.6f},{:.6f}\n", points[j].first, points[j].second, ghia[j],
                         fine.at_ghia[j], extrapolated[j]);
    if (results.size() >= 2)
      fmt::print(
          "cavity Re {:g}: Richardson extrapolation (N = {}, {}) deviates from Ghia by up to "
          "{:.4f} "
          "U\n",
          setup.re, results[last - 1].cells, fine.cells, limit_dev);
  }
  const auto name = [&](const LevelResult& r, const std::string& what) {
    return fmt::format("Re {:g} N={}: {}", setup.re, r.cells, what);
  };
  for (const auto& r : results)
    report.add(name(r, fmt::format("steady (max |du/dt| L/U^2 below {:g})", setup.tolerance)),
               r.change, 0, setup.tolerance, Check::at_most);
  report.add(name(fine, "max centreline deviation from Ghia / U"), std::max(fine.dev_u, fine.dev_v),
             0, setup.bound, Check::at_most);
  if (results.size() >= 2)
    report.add(
        fmt::format("Re {:g} deviation ratio N={} / N={}", setup.re, coarse.cells, fine.cells),
        std::max(coarse.dev_u, coarse.dev_v) / std::max(fine.dev_u, fine.dev_v), 1.0, 0,
        Check::at_least);
  if (results.size() >= 3)
    report.add(fmt::format("Re {:g}: observed order of the centreline profiles (self-convergence)",
                           setup.re),
               std::log2(results[last - 1].diff_to_coarser / fine.diff_to_coarser), setup.min_order,
               0, Check::at_least);
  return results;
}

void run_cases(const Context& ctx, Report& report) {
  ReSetup re100;
  re100.re = 100;
  re100.levels = ctx.quick ? std::vector<int>{16, 32} : std::vector<int>{24, 48, 96};
  re100.tolerance = ctx.quick ? 1e-3 : 1e-4;
  // Ghia's Re 100 table is itself a 129^2 second-order solution: its v extrema (0.17527,
  // -0.24533) differ from spectral solutions (0.1796, -0.2538) by up to 0.0085 U, and the
  // Richardson extrapolation of our 32^2/64^2 profiles gives 0.1795 and -0.2531: the deviation
  // from Ghia tends to ~0.95 % of U (at x = 0.8594), not to zero. Quick (32^2): measured
  // 1.7 %, = that limit + our h^2 error (0.6 % at h = 1/32) + the looser steady tolerance;
  // 2.5 % leaves margin.
  re100.bound = ctx.quick ? 0.025 : 0.01;
  // At least the scheme's order 2; measured 3.35 (24/48/96): the 24^2 pair is still
  // pre-asymptotic (not yet in the h^2 range), so only the lower bound is asserted.
  re100.min_order = 1.8;
  const auto r100 = run_re(ctx, report, re100);

  ReSetup re1000;
  re1000.re = 1000;
  re1000.levels = ctx.quick ? std::vector<int>{32, 64} : std::vector<int>{32, 64, 128};
  // --set re1000_finest=256 adds a fourth Re 1000 level (39 more minutes on a shared machine).
  if (!ctx.quick && ctx.option("re1000_finest") == "256") re1000.levels.push_back(256);
  re1000.tolerance = ctx.quick ? 1e-3 : 1e-4;
  re1000.t_max = 400;
  // The 1 % on the finest level (not reached, see the header: Ghia's own error at
  // x = 0.9453 is 1.85 % of U). Quick (64^2): measured 8.0 % at x = 0.9531, = Ghia's 1.8 % there +
  // our 6.2 % (the 128^2 error there x 5, still pre-asymptotic); 10 % catches a 25 % degradation.
  re1000.bound = ctx.quick ? 0.10 : 0.01;
  // Measured 2.78 (32/64/128).
  re1000.min_order = 1.8;
  const auto r1000 = run_re(ctx, report, re1000);

  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (rank != 0) return;
  std::ofstream conv(ctx.out_dir / "convergence.csv");
  conv << "re,cells,h,steps,time,wall_seconds,max_dev_u,max_dev_v,max_dev,diff_to_coarser\n";
  for (const auto& [re, results] : {std::pair{100, &r100}, std::pair{1000, &r1000}})
    for (const auto& r : *results)
      conv << fmt::format("{},{},{:.6g},{},{:.4f},{:.2f},{:.6e},{:.6e},{:.6e},{:.6e}\n", re,
                          r.cells, 1.0 / r.cells, r.steps, r.time, r.wall, r.dev_u, r.dev_v,
                          std::max(r.dev_u, r.dev_v), r.diff_to_coarser);
}

}  // namespace

Case cavity_case() {
  return {"cavity",
          "lid-driven cavity Re 100, centreline profiles vs Ghia et al. 1982",
          run_cases,
          {CaseOption::choice("re1000_finest",
                              "finest Re 1000 mesh (default 128; 256 adds ~40 min on a shared "
                              "machine)",
                              {"128", "256"})}};
}

}  // namespace valsalva::validation
