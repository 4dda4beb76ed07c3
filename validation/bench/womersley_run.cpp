// A Womersley pipe run through run::Simulation; see womersley_run.hpp.
#include "validation/bench/womersley_run.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "run/simulation.hpp"
#include "validation/gather_to_root.hpp"
#include "validation/nu_sgs_stats.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double kDensity = 1100, kViscosity = 3.6e-3, kPeriod = 1.0;

}  // namespace

std::vector<std::string> womersley_setup_overrides(const WomersleySetup& setup) {
  const double r = womersley_radius(setup.womersley), d = 2 * r;
  const double q0 = 5 * d / kPeriod * std::numbers::pi * r * r;
  const auto exact = flow::Womersley::from_sine(r, kViscosity / kDensity, q0, q0, kPeriod, 0.0);
  WomersleyLevel level = setup;
  level.dt = phase_steps(exact, kPeriod, setup.phases, setup.cfl, d / setup.nodes_per_diameter).dt;
  return womersley_overrides(level);
}

PhaseSteps phase_steps(const flow::Womersley& exact, double period, int phases, double cfl,
                       double h) {
  PhaseSteps s;
  for (int k = 0; k < 1000; ++k)
    s.u_peak = std::max(s.u_peak, exact.velocity(0.0, period * k / 1000));
  const double interval = period / phases;
  s.per_phase = static_cast<int>(std::ceil(interval / (cfl * h / s.u_peak)));
  s.dt = interval / s.per_phase;
  return s;
}

WomersleyResult run_womersley(const WomersleySetup& setup, MPI_Comm comm) {
  const double t0 = MPI_Wtime();
  WomersleyResult res;
  const double nu = kViscosity / kDensity;
  const double R = womersley_radius(setup.womersley), D = 2 * R;
  const double h = D / setup.nodes_per_diameter, L = setup.length_in_diameters * D;
  const double q0 = 5 * D / kPeriod * std::numbers::pi * R * R;
  res.radius = R, res.length = L, res.h = h;
  res.exact = flow::Womersley::from_sine(R, nu, q0, q0, kPeriod, 0.0);
  const auto& exact = res.exact;
  const auto steps = phase_steps(exact, kPeriod, setup.phases, setup.cfl, h);
  res.u_peak = steps.u_peak, res.dt = steps.dt;
  const std::int64_t per_phase = steps.per_phase;
  const std::int64_t first_sample = per_phase * setup.phases * setup.sample_period;
  auto radius_of = [&](const Eigen::Vector3d& x) { return std::min(std::hypot(x.x(), x.y()), R); };

  NuSgsStats nu_stats;
  SceneRun measure;
  measure.observer = [&](const run::Simulation& sim, std::int64_t step) {
    const auto& local = sim.local();
    const auto& velocity = sim.state().velocity;
    const auto& nu_sgs = sim.loop().subgrid_viscosity();
    nu_stats.add(local, nu_sgs, nu);
    for (int j = 0; j < (nu_sgs.empty() ? 0 : local.num_owned); ++j)
      if (std::abs(local.position[j].z() - L / 2) <= L / 6)
        res.interior_nu_ratio = std::max(res.interior_nu_ratio, nu_sgs[j] / nu);
    if (setup.max_steps > 0 || step <= first_sample || (step - first_sample) % per_phase != 0)
      return;
    PhaseSample s;
    s.time = sim.state().time;
    const double t = s.time;
    double e2 = 0, vol = 0, q = 0, qe = 0, region = 0;
    std::vector<double> mine;
    for (int j = 0; j < local.num_owned; ++j) {
      const auto& x = local.position[j];
      const auto& u = velocity[j];
      if (std::abs(x.z() - L / 2) <= L / 6) {
        q += local.volume[j] * u.z();
        qe += local.volume[j] * exact.velocity(radius_of(x), t);
        region += local.volume[j];
      }
      const bool slab = std::abs(x.z() - L / 2) <= h / 2;
      if (!slab && !setup.sample_whole_pipe) continue;
      const double r = radius_of(x), ue = exact.velocity(r, t);
      mine.insert(mine.end(), {x.x(), x.y(), x.z(), r, u.z(), ue, u.x(), u.y()});
      if (!slab) continue;
      s.max_error = std::max(s.max_error, std::abs(u.z() - ue));
      s.transverse = std::max(s.transverse, std::hypot(u.x(), u.y()));
      e2 += local.volume[j] * (u.z() - ue) * (u.z() - ue);
      vol += local.volume[j];
    }
    s.max_error = local.comm.max(s.max_error) / res.u_peak;
    s.transverse = local.comm.max(s.transverse) / res.u_peak;
    s.l2_error = std::sqrt(local.comm.sum(e2) / local.comm.sum(vol)) / res.u_peak;
    // The region's length is its dual volume / pi R^2, not L / 3: on the extruded pipe it holds
    // whole layers (7 h of the 6.7 h at D/10), which would bias the fluxes by 5 %.
    const double length = local.comm.sum(region) / (std::numbers::pi * R * R);
    s.mean_flux = local.comm.sum(q) / length, s.exact_mean_flux = local.comm.sum(qe) / length;
    s.flow_rate = q0 * (1 + std::sin(2 * std::numbers::pi * t / kPeriod));
    const auto all = gather_to_root(mine, comm);
    for (std::size_t i = 0; i + 7 < all.size(); i += 8) {
      s.x.push_back(all[i]), s.y.push_back(all[i + 1]), s.z.push_back(all[i + 2]);
      s.r.push_back(all[i + 3]), s.u.push_back(all[i + 4]), s.exact.push_back(all[i + 5]);
      s.ux.push_back(all[i + 6]), s.uy.push_back(all[i + 7]);
    }
    res.phases.push_back(std::move(s));
  };
  measure.at_end = [&](const run::Simulation& sim) {
    const auto& local = sim.local();
    res.nodes = local.global_nodes;
    res.max_nu_ratio = nu_stats.global_max(local);
    res.mean_nu_ratio = nu_stats.global_mean(local);
    res.interior_nu_ratio = local.comm.max(res.interior_nu_ratio);
    const auto nodes = sim.metrics().num_nodes();
    res.final_velocity = velocity_by_dual_node(local, sim.state().velocity, nodes);
    res.final_pressure = scalar_by_dual_node(local, sim.state().pressure, nodes);
  };
  const auto result =
      run_scene_file(womersley_scene(setup), womersley_setup_overrides(setup), {}, comm, measure);
  res.steps = result.summary.steps;
  res.max_divergence = result.summary.max_divergence;
  for (const auto& s : res.phases) {
    res.max_error = std::max(res.max_error, s.max_error);
    res.l2_error = std::max(res.l2_error, s.l2_error);
    res.transverse = std::max(res.transverse, s.transverse);
  }
  double wall = MPI_Wtime() - t0;
  MPI_Allreduce(MPI_IN_PLACE, &wall, 1, MPI_DOUBLE, MPI_MAX, comm);
  res.wall = wall;
  return res;
}

}  // namespace valsalva::validation
