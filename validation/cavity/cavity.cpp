// Lid-driven cavity (flow-solver issue, verification 4): unit square, lid y = 1 moving at U = 1
// in +x (wall velocity), the other three sides no-slip, a periodic slab of 3 hexahedral cells
// in z. Run from rest to steady state (max_j |u_j^{n+1} - u_j^n| / dt below a tolerance), then
// the centreline profiles u(y) at x = 1/2 and v(x) at y = 1/2 are compared with the table of
// U. Ghia, K.N. Ghia, C.T. Shin, J. Comput. Phys. 48 (1982) 387-411 (129^2 multigrid, stream
// function-vorticity; validation/refdata/ghia1982_cavity, see its SOURCE.txt for the known
// typos, none of which is in the Re 100 columns used here). The computed profile is the nodal
// line (N even: x = 1/2 and y = 1/2 are node lines), interpolated linearly at Ghia's points.
// Corner nodes belong to the side walls (a stationary wall wins over the moving lid), as in
// Ghia's discretisation where the lid velocity starts inside the corners.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "flow/boundary_conditions.hpp"
#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"
#include "io/box_generator.hpp"
#include "validation/case.hpp"

namespace valsalva::validation {

namespace {

struct Profile {
  std::vector<double> s, value;  // position along the line, velocity component
};

// Column `re_column` ("Re100") of a Ghia table (comment lines start with '#').
Profile read_ghia(const std::filesystem::path& file, const std::string& re_column) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cavity: cannot open " + file.string());
  std::string line;
  int column = -1, line_no = 0;
  Profile p;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (column < 0) {
      for (std::size_t k = 0; k < cells.size(); ++k)
        if (cells[k] == re_column) column = static_cast<int>(k);
      if (column < 0)
        throw std::runtime_error(fmt::format("cavity: {}:{}: no column '{}' in the header",
                                             file.string(), line_no, re_column));
      continue;
    }
    if (static_cast<int>(cells.size()) <= column)
      throw std::runtime_error(
          fmt::format("cavity: {}:{}: fewer than {} columns", file.string(), line_no, column + 1));
    p.s.push_back(std::stod(cells[0]));
    p.value.push_back(std::stod(cells[column]));
  }
  return p;
}

// Linear interpolation of a profile given at uniformly spaced nodes s_k = k / n.
double interpolate(const std::vector<double>& nodal, double s) {
  const int n = static_cast<int>(nodal.size()) - 1;
  const int k = std::clamp(static_cast<int>(std::floor(s * n)), 0, n - 1);
  const double w = s * n - k;
  return (1 - w) * nodal[k] + w * nodal[k + 1];
}

struct LevelResult {
  int cells = 0, steps = 0;
  double time = 0, wall = 0, dev_u = 0, dev_v = 0, change = 0;
  std::vector<double> at_ghia;  // computed u then v at Ghia's points
};

LevelResult run_level(const Context& ctx, int n, double re, double tolerance, double t_max,
                      const Profile& ghia_u, const Profile& ghia_v) {
  const double lid = 1.0, rho = 1.0, nu = lid * 1.0 / re;
  io::BoxSpec spec;
  spec.cells = {n, n, 3};
  spec.length = Eigen::Vector3d(1, 1, 3.0 / n);
  spec.periodic = {false, false, true};
  const auto mesh = io::generate_box(spec);
  const auto metrics = flow::compute_dual_metrics(mesh);
  const auto local = flow::distribute(mesh, metrics, ctx.comm);

  std::vector<flow::BoundarySpec> walls;
  for (const char* patch : {"xmin", "xmax", "ymin", "ymax"}) {
    flow::BoundarySpec w;
    w.patch = patch;
    w.type = flow::BoundaryType::wall;
    if (w.patch == "ymax") w.wall_velocity = Eigen::Vector3d(lid, 0, 0);
    walls.push_back(w);
  }
  flow::ProjectionOptions options;
  options.density = rho;
  options.viscosity = nu;
  options.poisson.tolerance = 1e-8;
  options.boundary = std::make_shared<flow::BoundaryConditions>(local, walls, nu);
  // flow::poisson_weights = the two-point weights on hexahedra. (A 15 % weaker vortex seen while
  // this case was written came from an intermediate version of the pressure damping without
  // its boundary-face term, fixed in the same commit series.)
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));

  flow::FlowState state;
  state.velocity.assign(local.num_local(), Eigen::Vector3d::Zero());
  state.pressure.assign(local.num_local(), 0.0);
  options.boundary->impose(state.velocity, 0.0);

  const auto weights = flow::laplacian_weights(local);
  std::vector<double> scratch;
  LevelResult r;
  r.cells = n;
  const auto start = std::chrono::steady_clock::now();
  double dt = 0;
  flow::VectorField previous;
  std::ofstream history;
  if (local.comm.root()) {
    history.open(ctx.out_dir / fmt::format("history_N{}.csv", n));
    history << "step,time,dt,max_change_rate\n";
  }
  while (true) {
    if (r.steps % 20 == 0) {  // sigma = 0.8 of the RK4 stability limit, refreshed as u grows
      const auto rates = flow::stability_rates(local, weights, nu, state.velocity, scratch);
      dt = 0.8 / rates.stability;
    }
    previous = state.velocity;
    solver.step(state, dt);
    ++r.steps;
    double change = 0;
    for (int i = 0; i < local.num_owned; ++i)
      change = std::max(change, (state.velocity[i] - previous[i]).cwiseAbs().maxCoeff());
    r.change = local.comm.max(change) / dt;  // m/s^2: max |du/dt|
    if (!std::isfinite(r.change))
      throw std::runtime_error(
          fmt::format("cavity N = {}: non-finite velocity at step {}", n, r.steps));
    if (history.is_open() && r.steps % 50 == 0)
      history << fmt::format("{},{:.6g},{:.6g},{:.6e}\n", r.steps, state.time, dt, r.change);
    // Converged: |du/dt| < tolerance U^2/L everywhere (the remaining distance to the steady
    // state is ~ tolerance / (slowest decay rate ~ 50 nu / L^2) in units of U).
    if (r.change < tolerance * lid * lid || state.time >= t_max) break;
  }
  r.time = state.time;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Centreline lines on the z = 0 node layer; owned nodes contribute, summed over ranks.
  std::vector<double> u_line(n + 1, 0.0), v_line(n + 1, 0.0);
  const double h = 1.0 / n, eps = 1e-6 * h;
  for (int i = 0; i < local.num_owned; ++i) {
    const auto& x = local.position[i];
    if (std::abs(x.z()) > eps) continue;
    const int ix = static_cast<int>(std::lround(x.x() / h));
    const int iy = static_cast<int>(std::lround(x.y() / h));
    if (ix == n / 2) u_line[iy] = state.velocity[i].x();
    if (iy == n / 2) v_line[ix] = state.velocity[i].y();
  }
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, u_line.data(), n + 1, MPI_DOUBLE, MPI_SUM, ctx.comm));
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, v_line.data(), n + 1, MPI_DOUBLE, MPI_SUM, ctx.comm));
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
    std::ofstream out(ctx.out_dir / fmt::format("profiles_N{}.csv", n));
    out << "s,u_at_x_half,v_at_y_half\n";
    for (int k = 0; k <= n; ++k)
      out << fmt::format("{:.8f},{:.10e},{:.10e}\n", k * h, u_line[k], v_line[k]);
    fmt::print(
        "cavity Re {:g} N = {}: {} steps to t = {:.2f} (max |du/dt| {:.2e}), wall {:.1f} s, max "
        "deviation from Ghia: u {:.4f} U, v {:.4f} U\n",
        re, n, r.steps, r.time, r.change, r.wall, r.dev_u, r.dev_v);
  }
  return r;
}

void run_cases(const Context& ctx, Report& report) {
  const auto dir = ctx.refdata_dir / "ghia1982_cavity";
  const auto ghia_u = read_ghia(dir / "ghia1982_u_vertical_centreline.csv", "Re100");
  const auto ghia_v = read_ghia(dir / "ghia1982_v_horizontal_centreline.csv", "Re100");
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  const bool rank0 = rank == 0;
  if (rank0) {  // Ghia's points next to the computed profiles, for plot.py
    std::ofstream out(ctx.out_dir / "ghia_Re100.csv");
    out << "line,s,value\n";
    for (std::size_t k = 0; k < ghia_u.s.size(); ++k)
      out << fmt::format("u,{},{}\n", ghia_u.s[k], ghia_u.value[k]);
    for (std::size_t k = 0; k < ghia_v.s.size(); ++k)
      out << fmt::format("v,{},{}\n", ghia_v.s[k], ghia_v.value[k]);
  }
  // Quick: 16^2 and 32^2 (~4 s). Full: 24^2, 48^2, 96^2 (~8 min; 128^2 would take ~20 min,
  // the time step being viscous-limited, dt ~ h^2 / nu).
  const std::vector<int> levels =
      ctx.quick ? std::vector<int>{16, 32} : std::vector<int>{24, 48, 96};
  const double tolerance = ctx.quick ? 1e-3 : 1e-4;
  std::vector<LevelResult> results;
  for (int n : levels) results.push_back(run_level(ctx, n, 100, tolerance, 200, ghia_u, ghia_v));
  // Self-convergence: D_k = max over Ghia's points of |profile_{2N} - profile_N|.
  std::vector<double> self_diff(results.size(), 0.0);
  for (std::size_t k = 1; k < results.size(); ++k)
    for (std::size_t j = 0; j < results[k].at_ghia.size(); ++j)
      self_diff[k] =
          std::max(self_diff[k], std::abs(results[k].at_ghia[j] - results[k - 1].at_ghia[j]));
  if (rank0) {
    std::ofstream conv(ctx.out_dir / "convergence.csv");
    conv << "cells,h,steps,time,wall_seconds,max_dev_u,max_dev_v,max_dev,diff_to_coarser\n";
    for (std::size_t k = 0; k < results.size(); ++k) {
      const auto& r = results[k];
      conv << fmt::format("{},{:.6g},{},{:.4f},{:.2f},{:.6e},{:.6e},{:.6e},{:.6e}\n", r.cells,
                          1.0 / r.cells, r.steps, r.time, r.wall, r.dev_u, r.dev_v,
                          std::max(r.dev_u, r.dev_v), self_diff[k]);
    }
  }
  for (const auto& r : results)
    report.add(fmt::format("N={}: steady (max |du/dt| L/U^2 below {:g})", r.cells, tolerance),
               r.change, 0, tolerance, Check::at_most);
  // Ghia's Re 100 table is itself a 129^2 second-order solution: its v extrema (0.17527,
  // -0.24533) differ from spectral solutions (0.1796, -0.2538) by up to 0.0085 U, and the
  // Richardson extrapolation of our 32^2/64^2 profiles gives 0.1795 and -0.2531: the deviation
  // from Ghia tends to ~0.95 % of U (at x = 0.8594), not to zero. Quick (32^2): measured
  // 1.5 %, = that limit + our h^2 error (0.6 % at h = 1/32); 2.5 % leaves margin.
  const auto& fine = results.back();
  report.add(fmt::format("N={}: max centreline deviation from Ghia / U", fine.cells),
             std::max(fine.dev_u, fine.dev_v), 0, ctx.quick ? 0.025 : 0.01, Check::at_most);
  const auto& coarse = results.front();
  report.add(fmt::format("deviation ratio N={} / N={}", coarse.cells, fine.cells),
             std::max(coarse.dev_u, coarse.dev_v) / std::max(fine.dev_u, fine.dev_v), 1.0, 0,
             Check::at_least);
  if (results.size() >= 3) {
    // At least the scheme's order 2; measured 3.33 (24/48/96): the 24^2 pair is still
    // pre-asymptotic (not yet in the h^2 range), so only the lower bound is asserted.
    const double order = std::log2(self_diff[results.size() - 2] / self_diff.back());
    report.add("observed order of the centreline profiles (self-convergence)", order, 1.8, 0,
               Check::at_least);
  }
}

}  // namespace

Case cavity_case() {
  return {"cavity", "lid-driven cavity Re 100, centreline profiles vs Ghia et al. 1982", run_cases};
}

}  // namespace valsalva::validation
