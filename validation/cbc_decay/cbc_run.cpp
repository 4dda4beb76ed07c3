// Comte-Bellot & Corrsin decaying turbulence run; see cbc_run.hpp.
#include "validation/cbc_decay/cbc_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <stdexcept>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"
#include "io/box_generator.hpp"
#include "les/cbc_data.hpp"
#include "les/derivative_skewness.hpp"
#include "les/energy_spectrum.hpp"
#include "les/random_field.hpp"
#include "les/spectrum_rescale.hpp"
#include "les/subgrid_viscosity.hpp"

namespace valsalva::validation {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}
// CPU time of the calling thread: on a shared machine the wall clock also counts the time the
// process waits for a core, which made the subgrid share of a step meaningless.
double thread_cpu() {
  timespec c;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c);
  return static_cast<double>(c.tv_sec) + 1e-9 * static_cast<double>(c.tv_nsec);
}

// Grid index (k n + j) n + i of every local node (box nodes sit at multiples of h).
std::vector<std::size_t> grid_index(const flow::LocalMesh& local, int n, double h) {
  std::vector<std::size_t> idx(local.num_local());
  for (int a = 0; a < local.num_local(); ++a) {
    std::size_t id = 0;
    for (int d = 2; d >= 0; --d) {
      const long c = ((std::lround(local.position[a][d] / h) % n) + n) % n;
      id = id * n + static_cast<std::size_t>(c);
    }
    idx[a] = id;
  }
  return idx;
}

// The owned velocities as three n^3 grid arrays (u, v, w one after the other) on every rank.
std::vector<double> gather(const flow::LocalMesh& local, const std::vector<std::size_t>& idx, int n,
                           const flow::VectorField& u) {
  const std::size_t n3 = static_cast<std::size_t>(n) * n * n;
  std::vector<double> field(3 * n3, 0.0);
  for (int a = 0; a < local.num_owned; ++a)
    for (int c = 0; c < 3; ++c) field[c * n3 + idx[a]] = u[a][c];
  MPI_Allreduce(MPI_IN_PLACE, field.data(), static_cast<int>(field.size()), MPI_DOUBLE, MPI_SUM,
                local.comm.get());
  return field;
}

// Spectrum of the owned velocities (gathered on every rank) against the filtered measurement.
CbcStation measure(const flow::LocalMesh& local, const std::vector<std::size_t>& idx, int n,
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

}  // namespace

CbcResult run_cbc(const CbcSpec& spec, MPI_Comm comm) {
  const auto start = Clock::now();
  const double M = les::cbc_mesh_size, U0 = les::cbc_u0;
  const double length = spec.box_in_m * M, h = length / spec.n;
  io::BoxSpec box;
  box.cells = {spec.n, spec.n, spec.n};
  box.length = Eigen::Vector3d::Constant(length);
  box.periodic = {true, true, true};
  const auto mesh = io::generate_box(box);
  const auto metrics = flow::compute_dual_metrics(mesh);
  const auto local = flow::distribute(mesh, metrics, comm, {2, "metis"});
  const auto idx = grid_index(local, spec.n, h);

  const auto data = les::read_cbc_table3(spec.table.string());
  auto table = [&](int station) { return data.at(station).table(les::Extrapolation::power_law); };

  // Initial field: the start station's spectrum (42 unless a study asks otherwise) on shells
  // 1 .. n/2 - 1, the same on every rank.
  const std::size_t n3 = static_cast<std::size_t>(spec.n) * spec.n * spec.n;
  std::vector<double> u0(n3), v0(n3), w0(n3);
  const int start_station = spec.start_station;
  const auto start_spectrum = table(start_station);
  les::random_solenoidal_field([&](double k) { return start_spectrum(k); }, spec.n, length,
                               spec.seed, u0, v0, w0);
  flow::FlowState state;
  for (int a = 0; a < local.num_local(); ++a) {
    state.velocity.emplace_back(u0[idx[a]], v0[idx[a]], w0[idx[a]]);
    state.pressure.push_back(0.0);
  }

  flow::ProjectionOptions options;
  options.density = 1.2;
  options.viscosity = cbc_air_viscosity;
  options.scheme = spec.scheme;
  options.poisson.tolerance = 1e-8;
  CbcResult r;
  r.nodes = local.global_nodes;
  std::unique_ptr<les::SubgridViscosity> sgs;
  if (spec.model != "none") {
    sgs = std::make_unique<les::SubgridViscosity>(spec.model, spec.constant, local.h,
                                                  les::parse_sgs_update(spec.update));
    options.subgrid_viscosity = [&](int stage, const flow::TensorField& g, flow::ScalarField& nu) {
      const double t0 = thread_cpu();
      (*sgs)(stage, g, nu);
      r.sgs_seconds += thread_cpu() - t0;
    };
  }
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));

  std::vector<double> scratch;
  const double time_scale = M / U0;  // s per unit of tU0/M
  // Steps to t_end at `spec.stability` of the RK4 limit for nu + max nu_sgs; after_step runs
  // after each step.
  auto advance_to = [&](double t_end, const auto& after_step) {
    while (t_end - state.time > 1e-12 * t_end) {
      const double nu = options.viscosity + solver.max_subgrid_viscosity();
      const auto rates =
          flow::stability_rates(local, solver.laplacian_weights(), nu, state.velocity, scratch);
      double dt = spec.stability / rates.stability;
      const double remaining = t_end - state.time;
      if (remaining <= dt * (1 + 1e-9))
        dt = remaining;
      else if (remaining < 2 * dt)
        dt = remaining / 2;
      const double t0 = thread_cpu();
      solver.step(state, dt);
      r.step_seconds += thread_cpu() - t0;
      after_step();
    }
  };
  // Spin-up: the random phases have no triple correlations (no energy transfer); run and rescale
  // back to the start spectrum after every step, then restart the clock at the start station.
  auto skewness = [&](const std::vector<double>& field) {
    return les::derivative_skewness({field.data(), n3}, {field.data() + n3, n3},
                                    {field.data() + 2 * n3, n3}, spec.n, length);
  };
  r.spinup_u0_over_m =
      spec.spinup_turnovers * les::large_scales(start_spectrum).turnover_time / time_scale;
  if (r.spinup_u0_over_m > 0) {
    advance_to(r.spinup_u0_over_m * time_scale, [&] {
      auto field = gather(local, idx, spec.n, state.velocity);
      if (spec.record_skewness) {
        r.spinup_time_u0_over_m.push_back(state.time / time_scale);
        r.spinup_skewness.push_back(skewness(field));
      }
      les::rescale_to_spectrum([&](double k) { return start_spectrum(k); }, spec.n, length,
                               {field.data(), n3}, {field.data() + n3, n3},
                               {field.data() + 2 * n3, n3});
      for (int a = 0; a < local.num_local(); ++a)
        state.velocity[a] = {field[idx[a]], field[n3 + idx[a]], field[2 * n3 + idx[a]]};
      ++r.spinup_steps;
    });
    state.time = 0;
  }

  r.initial = measure(local, idx, spec.n, length, state.velocity, start_spectrum, start_station);
  auto energy = [&] {
    return flow::kinetic_energy(local, 1.0, state.velocity) / (length * length * length);
  };
  r.time_u0_over_m.push_back(start_station);
  r.energy.push_back(energy());
  if (spec.record_skewness)
    r.skewness.push_back(skewness(gather(local, idx, spec.n, state.velocity)));
  for (int station : spec.stations) {
    if (station <= start_station)
      throw std::invalid_argument(fmt::format(
          "run_cbc: station {} is not after the start at tU0/M = {}", station, start_station));
    advance_to((station - start_station) * time_scale, [&] {
      ++r.steps;
      r.time_u0_over_m.push_back(start_station + state.time / time_scale);
      r.energy.push_back(energy());
      if (spec.record_skewness)
        r.skewness.push_back(skewness(gather(local, idx, spec.n, state.velocity)));
      if (!std::isfinite(r.energy.back()))
        throw std::runtime_error(fmt::format("run_cbc: {} {}^3 blew up at tU0/M = {:.2f}",
                                             spec.model, spec.n, r.time_u0_over_m.back()));
    });
    auto s = measure(local, idx, spec.n, length, state.velocity, table(station), station);
    s.max_nu_sgs_over_nu = solver.max_subgrid_viscosity() / options.viscosity;
    r.stations.push_back(std::move(s));
  }
  r.step_seconds = local.comm.max(r.step_seconds);
  r.sgs_seconds = local.comm.max(r.sgs_seconds);
  r.wall_seconds = local.comm.max(seconds(start));
  return r;
}

}  // namespace valsalva::validation
