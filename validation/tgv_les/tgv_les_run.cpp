// Taylor-Green vortex Re 1600 with a subgrid model; see tgv_les_run.hpp.
#include "validation/tgv_les/tgv_les_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "flow/run_diagnostics.hpp"
#include "run/simulation.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {
double cpu_seconds() {
  timespec c;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c);
  return c.tv_sec + 1e-9 * c.tv_nsec;
}
}  // namespace

flow::FlowState tgv_re1600_initial_state(const mesh::LocalMesh& local) {
  flow::FlowState state;
  for (const auto& x : local.position) {
    state.velocity.emplace_back(std::sin(x.x()) * std::cos(x.y()) * std::cos(x.z()),
                                -std::cos(x.x()) * std::sin(x.y()) * std::cos(x.z()), 0.0);
    state.pressure.push_back((std::cos(2 * x.x()) + std::cos(2 * x.y())) *
                             (std::cos(2 * x.z()) + 2) / 16);
  }
  return state;
}

double tgv_mean_energy(const mesh::LocalMesh& local, const flow::VectorField& u) {
  double e = 0;
  for (int i = 0; i < local.num_owned; ++i) e += 0.5 * local.volume[i] * u[i].squaredNorm();
  return local.comm.sum(e) / std::pow(2 * std::numbers::pi, 3);
}

TgvLesResult run_tgv_les(const TgvLesSpec& spec, int n, MPI_Comm comm,
                         const std::filesystem::path& run_dir) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double two_pi = 2 * std::numbers::pi, nu = 1.0 / 1600;
  TgvLesResult r;
  const double h = two_pi / n;
  r.steps = static_cast<int>(std::ceil(spec.t_end / (spec.cfl * h)));
  r.dt = spec.t_end / r.steps;
  std::vector<double> scratch;
  double cpu0 = 0;
  auto loop0 = std::chrono::steady_clock::now();
  SceneRun measure;
  measure.at_start = [&](const run::Simulation& sim) {
    r.time.push_back(0);
    r.energy.push_back(tgv_mean_energy(sim.local(), sim.state().velocity));
    r.max_nu_sgs_over_nu.push_back(0);
    cpu0 = cpu_seconds();
    loop0 = std::chrono::steady_clock::now();
  };
  double observer_cpu = 0;  // these per-step diagnostics are the measurement's, not the run's
  measure.observer = [&](const run::Simulation& sim, std::int64_t) {
    const double observer_start = cpu_seconds();
    const auto& solver = sim.loop().solver();
    const auto& state = sim.state();
    r.time.push_back(state.time);
    r.energy.push_back(tgv_mean_energy(sim.local(), state.velocity));
    r.max_nu_sgs_over_nu.push_back(solver.max_subgrid_viscosity() / nu);
    // The run loop's RK4 stability number (derived for central2) of this fixed dt.
    const double nu_total = nu + solver.max_subgrid_viscosity();
    r.max_stability_number =
        std::max(r.max_stability_number,
                 r.dt * flow::stability_rates(sim.local(), solver.laplacian_weights(), nu_total,
                                              state.velocity, scratch)
                            .stability);
    // Blown up: energy no longer finite, or above its initial value (viscous decay only).
    if (!(r.energy.back() <= r.energy.front())) {
      r.blow_up_time = state.time;
      sim.request_stop();  // the energy is a global sum: every rank stops here
    }
    observer_cpu += cpu_seconds() - observer_start;
  };
  measure.at_end = [&](const run::Simulation& sim) {
    r.cpu_seconds = sim.local().comm.sum(cpu_seconds() - cpu0 - observer_cpu);
    r.loop_wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - loop0).count();
  };
  std::vector<std::string> overrides{
      fmt::format("mesh.box.cells=[{0}, {0}, {0}]", n),
      fmt::format("flow.scheme={}", spec.scheme),
      fmt::format("les.model={}", spec.model),
      fmt::format("les.update={}", spec.update),
      fmt::format("les.constant={:.17g}", spec.constant),
      fmt::format("time.end={:.17g}", spec.t_end),
      fmt::format("time.dt={:.17g}", r.dt),
      fmt::format("flow.fourth_order_operators={}", spec.fourth_order_operators)};
  overrides.insert(overrides.end(), spec.overrides.begin(), spec.overrides.end());
  const auto result =
      run_scene_file(case_scene("tgv_les", "tgv_les.toml"), overrides, run_dir, comm, measure);
  r.poisson_iterations_max = result.summary.max_poisson_iterations;
  r.poisson_iterations_mean =
      result.summary.steps > 0
          ? double(result.summary.total_poisson_iterations) / double(result.summary.steps)
          : 0.0;
  r.wall_seconds = core::Comm(comm).max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
  return r;
}

std::vector<std::array<double, 3>> read_tgv_reference(const std::filesystem::path& file) {
  // time, energy, dissipation rate, enstrophy; blank-separated under '#' comments.
  const auto table = core::read_numeric_table(file, core::TableHeader::none, 4, true);
  std::vector<std::array<double, 3>> rows;
  for (const auto& r : table.rows) rows.push_back({r[0], r[1], r[2]});
  if (rows.size() < 2) throw std::runtime_error("no data rows in " + file.string());
  return rows;
}

double interpolate_tgv_reference(const std::vector<std::array<double, 3>>& ref, double t,
                                 int column) {
  std::size_t i = 1;
  while (i + 1 < ref.size() && ref[i][0] < t) ++i;
  const double w = (t - ref[i - 1][0]) / (ref[i][0] - ref[i - 1][0]);
  return (1 - w) * ref[i - 1][column] + w * ref[i][column];
}

TgvDissipation tgv_dissipation(const TgvLesResult& r, const std::vector<std::array<double, 3>>& ref,
                               double t_end) {
  TgvDissipation d;
  for (const auto& row : ref)
    if (row[0] <= t_end && row[2] > d.reference_peak)
      d.reference_peak = row[2], d.reference_peak_time = row[0];
  for (std::size_t i = 1; i + 1 < r.time.size(); ++i) {
    const double rate = -(r.energy[i + 1] - r.energy[i - 1]) / (r.time[i + 1] - r.time[i - 1]);
    d.time.push_back(r.time[i]);
    d.rate.push_back(rate);
    d.reference.push_back(interpolate_tgv_reference(ref, r.time[i], 2));
    d.max_error = std::max(d.max_error, std::abs(rate - d.reference.back()));
    if (rate > d.peak) d.peak = rate, d.peak_time = r.time[i];
  }
  d.max_error /= d.reference_peak;
  return d;
}

}  // namespace valsalva::validation
