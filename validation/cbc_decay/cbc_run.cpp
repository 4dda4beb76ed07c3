// Comte-Bellot & Corrsin decaying turbulence run; see cbc_run.hpp.
#include "validation/cbc_decay/cbc_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <stdexcept>

#include "core/comm.hpp"
#include "core/thread_cpu_time.hpp"
#include "flow/run_diagnostics.hpp"
#include "les/cbc_data.hpp"
#include "les/derivative_skewness.hpp"
#include "les/energy_spectrum.hpp"
#include "les/random_field.hpp"
#include "les/spectrum_rescale.hpp"
#include "mesh/local_mesh.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

// The owned velocities as three n^3 grid arrays (u, v, w one after the other) on every rank.
std::vector<double> gather(const mesh::LocalMesh& local, const std::vector<std::size_t>& idx, int n,
                           const flow::VectorField& u) {
  const std::size_t n3 = static_cast<std::size_t>(n) * n * n;
  std::vector<double> field(3 * n3, 0.0);
  for (int a = 0; a < local.num_owned; ++a)
    for (int c = 0; c < 3; ++c) field[c * n3 + idx[a]] = u[a][c];
  local.comm.sum_in_place(field);
  return field;
}

// Spectrum of the owned velocities (gathered on every rank) against the filtered measurement.
CbcStation measure(const mesh::LocalMesh& local, const std::vector<std::size_t>& idx, int n,
                   double length, const flow::VectorField& u, const les::SpectrumTable& exp,
                   int station) {
  const std::size_t n3 = static_cast<std::size_t>(n) * n * n;
  const auto field = gather(local, idx, n, u);
  const auto spec = les::energy_spectrum({field.data(), n3}, {field.data() + n3, n3},
                                         {field.data() + 2 * n3, n3}, n, length);
  CbcStation s;
  s.t_u0_over_m = station;
  for (int shell = 1; shell <= n / 2 - 1; ++shell) {
    s.k.push_back(spec.k[shell]);
    s.E.push_back(spec.E[shell]);
    s.E_exp.push_back(exp(spec.k[shell]));
    s.resolved += spec.E[shell] * spec.dk;
    s.resolved_exp += s.E_exp.back() * spec.dk;
  }
  return s;
}

// The level as scene overrides of validation/cbc_decay/cbc_decay.toml: the box, the model, the
// scheme, the time-step fraction, the end and the times landed on (spin-up end and stations).
std::vector<std::string> level_overrides(const CbcSpec& spec, double length, double end,
                                         const std::vector<double>& land_on) {
  std::string times;
  for (double t : land_on) times += fmt::format("{}{:.17g}", times.empty() ? "" : ", ", t);
  return {fmt::format("mesh.box.cells=[{0}, {0}, {0}]", spec.n),
          fmt::format("mesh.box.length=[{0:.17g}, {0:.17g}, {0:.17g}]", length),
          fmt::format("flow.density={:.17g}", cbc_air_density),
          fmt::format("flow.viscosity={:.17g}", cbc_air_density * cbc_air_viscosity),
          fmt::format("flow.scheme={}", spec.scheme),
          fmt::format("les.model={}", spec.model),
          fmt::format("les.constant={:.17g}", spec.constant),
          fmt::format("les.update={}", spec.update),
          fmt::format("time.stability_fraction={:.17g}", spec.stability),
          fmt::format("time.end={:.17g}", end),
          fmt::format("time.land_on=[{}]", times)};
}

}  // namespace

// One scene run (validation/cbc_decay/cbc_decay.toml through run::Simulation): the spin-up from
// t = 0 to t_s, then the decay from the start station (at t_s) to the last station. The
// private loop this replaces restarted the clock at t_s; here the stations sit at t_s +
// (station - start) M / U0 and every time reported is counted from t_s, so the steps are the
// same up to the rounding of t_s + (...) (the pressure, the solver's nu_sgs and its Poisson warm
// start carry over from the spin-up as they did).
CbcResult run_cbc(const CbcSpec& spec, MPI_Comm comm) {
  const auto start = Clock::now();
  const double M = les::cbc_mesh_size, U0 = les::cbc_u0;
  const double length = spec.box_in_m * M, h = length / spec.n;
  const double time_scale = M / U0;  // s per unit of tU0/M
  const int start_station = spec.start_station;
  for (int station : spec.stations)
    if (station <= start_station)
      throw std::invalid_argument(fmt::format(
          "run_cbc: station {} is not after the start at tU0/M = {}", station, start_station));
  const std::size_t n3 = static_cast<std::size_t>(spec.n) * spec.n * spec.n;
  const auto data = les::read_cbc_table3(spec.table.string());
  auto table = [&](int station) { return data.at(station).table(les::Extrapolation::power_law); };

  // Initial field: the start station's spectrum (42 unless a study asks otherwise) on shells
  // 1 .. n/2 - 1, the same on every rank; box nodes sit at multiples of h.
  std::vector<double> u0(n3), v0(n3), w0(n3);
  const auto start_spectrum = table(start_station);
  les::random_solenoidal_field([&](double k) { return start_spectrum(k); }, spec.n, length,
                               spec.seed, u0, v0, w0);
  auto node_index = [&](const Eigen::Vector3d& x) {
    std::size_t id = 0;
    for (int d = 2; d >= 0; --d) {
      const long c = ((std::lround(x[d] / h) % spec.n) + spec.n) % spec.n;
      id = id * spec.n + static_cast<std::size_t>(c);
    }
    return id;
  };

  CbcResult r;
  // Spin-up: the random phases have no triple correlations (no energy transfer); run and rescale
  // back to the start spectrum after every step up to t_s (see cbc_decay.cpp).
  r.spinup_u0_over_m =
      spec.spinup_turnovers * les::large_scales(start_spectrum).turnover_time / time_scale;
  const double t_spin = r.spinup_u0_over_m * time_scale;
  std::vector<double> land_on;
  if (t_spin > 0) land_on.push_back(t_spin);
  for (int station : spec.stations)
    land_on.push_back(t_spin + (station - start_station) * time_scale);
  const double t_end = land_on.back();
  const double eps = 1e-12 * t_end;  // the run loop's

  std::vector<std::size_t> idx;  // grid index of every local node
  auto skewness = [&](const std::vector<double>& field) {
    return les::derivative_skewness({field.data(), n3}, {field.data() + n3, n3},
                                    {field.data() + 2 * n3, n3}, spec.n, length);
  };
  auto energy = [&](const run::Simulation& sim) {
    return flow::kinetic_energy(sim.local(), 1.0, sim.state().velocity) /
           (length * length * length);
  };
  std::size_t next_station = 0;
  double cpu_mark = 0;  // thread CPU at the end of the last measurement
  // The start station's measurements (after the spin-up, or at t = 0 without one).
  auto at_start_station = [&](const run::Simulation& sim) {
    r.initial = measure(sim.local(), idx, spec.n, length, sim.state().velocity, start_spectrum,
                        start_station);
    r.time_u0_over_m.push_back(start_station);
    r.energy.push_back(energy(sim));
    if (spec.record_skewness)
      r.skewness.push_back(skewness(gather(sim.local(), idx, spec.n, sim.state().velocity)));
  };

  SceneRun run;
  run.initial_velocity = [&](const Eigen::Vector3d& x) {
    const auto id = node_index(x);
    return Eigen::Vector3d(u0[id], v0[id], w0[id]);
  };
  run.at_start = [&](const run::Simulation& sim) {
    const auto& local = sim.local();
    r.nodes = local.global_nodes;
    idx.resize(local.num_local());
    for (int a = 0; a < local.num_local(); ++a) idx[a] = node_index(local.position[a]);
    if (t_spin <= 0) at_start_station(sim);
    cpu_mark = core::thread_cpu_seconds();
  };
  if (t_spin > 0)
    run.modify_velocity = [&](const run::Simulation& sim, flow::VectorField& u, std::int64_t) {
      if (sim.state().time > t_spin + eps) return;
      auto field = gather(sim.local(), idx, spec.n, u);
      if (spec.record_skewness) {
        r.spinup_time_u0_over_m.push_back(sim.state().time / time_scale);
        r.spinup_skewness.push_back(skewness(field));
      }
      les::rescale_to_spectrum([&](double k) { return start_spectrum(k); }, spec.n, length,
                               {field.data(), n3}, {field.data() + n3, n3},
                               {field.data() + 2 * n3, n3});
      for (std::size_t a = 0; a < u.size(); ++a)
        u[a] = {field[idx[a]], field[n3 + idx[a]], field[2 * n3 + idx[a]]};
      ++r.spinup_steps;
    };
  run.observer = [&](const run::Simulation& sim, std::int64_t) {
    r.step_seconds += core::thread_cpu_seconds() - cpu_mark;
    const double t = sim.state().time;
    if (t <= t_spin + eps) {  // a spin-up step
      if (std::abs(t - t_spin) <= eps) at_start_station(sim);
      cpu_mark = core::thread_cpu_seconds();
      return;
    }
    ++r.steps;
    r.time_u0_over_m.push_back(start_station + (t - t_spin) / time_scale);
    r.energy.push_back(energy(sim));
    if (spec.record_skewness)
      r.skewness.push_back(skewness(gather(sim.local(), idx, spec.n, sim.state().velocity)));
    if (!std::isfinite(r.energy.back()))
      throw std::runtime_error(fmt::format("run_cbc: {} {}^3 blew up at tU0/M = {:.2f}", spec.model,
                                           spec.n, r.time_u0_over_m.back()));
    if (next_station < spec.stations.size() &&
        std::abs(t - land_on[land_on.size() - spec.stations.size() + next_station]) <= eps) {
      const int station = spec.stations[next_station++];
      auto s =
          measure(sim.local(), idx, spec.n, length, sim.state().velocity, table(station), station);
      s.max_nu_sgs_over_nu = sim.loop().solver().max_subgrid_viscosity() / cbc_air_viscosity;
      r.stations.push_back(std::move(s));
    }
    cpu_mark = core::thread_cpu_seconds();
  };
  run.at_end = [&](const run::Simulation& sim) { r.sgs_seconds = sim.subgrid_cpu_seconds(); };
  run_scene_file(case_scene("cbc_decay", "cbc_decay.toml"),
                 level_overrides(spec, length, t_end, land_on), {}, comm, run);
  if (r.stations.size() != spec.stations.size())
    throw std::logic_error(fmt::format("run_cbc: {} of {} stations measured", r.stations.size(),
                                       spec.stations.size()));
  const core::Comm c(comm);
  r.sgs_seconds = c.max(r.sgs_seconds);
  r.step_seconds = c.max(r.step_seconds);
  r.wall_seconds = c.max(seconds(start));
  return r;
}

}  // namespace valsalva::validation
