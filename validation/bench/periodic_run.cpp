// A streamwise-periodic Womersley pipe run; see periodic_run.hpp.
#include "validation/bench/periodic_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "flow/boundary_conditions.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "les/subgrid_viscosity.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/periodic_pipe_generator.hpp"
#include "validation/bench/womersley_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double kDensity = 1100, kViscosity = 3.6e-3, kPeriod = 1.0;

}  // namespace

PeriodicResult run_periodic_womersley(const PeriodicSetup& setup, MPI_Comm comm) {
  const double t0 = MPI_Wtime();
  PeriodicResult res;
  const double nu = kViscosity / kDensity, omega = 2 * std::numbers::pi / kPeriod;
  const double R = setup.womersley * std::sqrt(nu / omega), D = 2 * R;
  const double h = D / setup.nodes_per_diameter;
  const double q0 = 5 * D / kPeriod * std::numbers::pi * R * R;
  res.radius = R, res.h = h;

  mesh::PeriodicPipeSpec spec;
  spec.radius = R, spec.length = setup.layers * h, spec.target_size = h;
  spec.layers = setup.layers, spec.split = setup.split;
  const auto mesh = mesh::generate_periodic_pipe_mesh(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, comm);
  res.nodes = local.global_nodes;
  auto bc = std::make_shared<flow::BoundaryConditions>(
      local, std::vector<flow::BoundarySpec>{flow::boundary_spec("wall", flow::BoundaryType::wall)},
      nu);
  const auto exact = flow::Womersley::from_sine(R, nu, q0, q0, kPeriod, 0.0);
  res.exact = exact;

  flow::ProjectionOptions options;
  options.density = kDensity;
  options.viscosity = nu;
  options.poisson.tolerance = 1e-12;
  options.boundary = bc;
  std::unique_ptr<les::SubgridViscosity> model;
  NuSgsRecord record;  // every RK stage: the largest nu_sgs the model produces anywhere
  if (setup.les_model != "none") {
    model = std::make_unique<les::SubgridViscosity>(setup.les_model, std::nullopt, local.h);
    options.subgrid_viscosity = [&](int, const flow::TensorField& g, flow::ScalarField& nu_sgs) {
      (*model)(g, nu_sgs);
      record.add(local, nu_sgs, nu);
    };
  }
  // On prisms poisson_weights gives the two-point weights (P1 weights need tetrahedra); the
  // exact flow is divergence-free and dp stays at round-off, so the Poisson operator is not
  // exercised by this case.
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));
  solver.set_body_force([&](int, double t, const flow::VectorField&, flow::VectorField& f) {
    const Eigen::Vector3d force(0, 0, kDensity * exact.pressure_gradient(t));
    std::fill(f.begin(), f.end(), force);
  });

  const auto radius_of = [&](const Eigen::Vector3d& x) {
    return std::min(std::hypot(x.x(), x.y()), R);
  };
  flow::FlowState state;
  const int n = local.num_local();
  state.velocity.assign(n, Eigen::Vector3d::Zero());
  state.pressure.assign(n, 0.0);
  for (int j = 0; j < n; ++j)
    state.velocity[j].z() = exact.velocity(radius_of(local.position[j]), 0);
  bc->impose(state.velocity, 0.0);

  const auto steps = phase_steps(exact, kPeriod, setup.phases, setup.cfl, h);
  res.u_peak = steps.u_peak, res.dt = steps.dt;
  const int per_phase = steps.per_phase;
  const double dt = steps.dt;

  std::vector<double> mine;
  auto sample = [&](double t) {
    double e2 = 0, vol = 0, emax = 0, q = 0, qe = 0;
    for (int j = 0; j < local.num_owned; ++j) {
      const double r = radius_of(local.position[j]), ue = exact.velocity(r, t);
      const double u = state.velocity[j].z();
      q += local.volume[j] * u, qe += local.volume[j] * ue;
      emax = std::max(emax, std::abs(u - ue));
      e2 += local.volume[j] * (u - ue) * (u - ue);
      vol += local.volume[j];
      mine.insert(mine.end(), {t, r, u, ue});
    }
    res.max_error = std::max(res.max_error, local.comm.max(emax) / res.u_peak);
    res.mean_flux.push_back(local.comm.sum(q) / spec.length);
    res.exact_mean_flux.push_back(local.comm.sum(qe) / spec.length);
    res.flow_rate.push_back(q0 * (1 + std::sin(omega * t)));
    res.l2_error =
        std::max(res.l2_error, std::sqrt(local.comm.sum(e2) / local.comm.sum(vol)) / res.u_peak);
  };
  const int total = per_phase * setup.phases * setup.periods;
  const int first_sample = per_phase * setup.phases * (setup.periods - 1);
  double transverse = 0;
  for (int step = 1; step <= total; ++step) {
    const auto report = solver.step(state, dt);
    res.max_divergence = std::max(res.max_divergence, report.max_divergence);
    if (!std::isfinite(report.max_divergence) || report.max_divergence > 1e6)
      throw std::runtime_error(fmt::format(
          "womersley_periodic: the run blew up at step {} (t = {:.4g} s, max |div u| {:.3g} 1/s)",
          step, state.time, report.max_divergence));
    if (setup.flux_driven) {
      double q = 0, free = 0;
      for (int j = 0; j < local.num_owned; ++j) {
        q += local.volume[j] * state.velocity[j].z();
        if (radius_of(local.position[j]) < R * (1 - 1e-9)) free += local.volume[j];
      }
      const double du =
          (q0 * (1 + std::sin(omega * state.time)) * spec.length - local.comm.sum(q)) /
          local.comm.sum(free);
      for (int j = 0; j < n; ++j)
        if (radius_of(local.position[j]) < R * (1 - 1e-9)) state.velocity[j].z() += du;
    }
    for (int j = 0; j < local.num_owned; ++j)
      transverse = std::max(transverse, std::hypot(state.velocity[j].x(), state.velocity[j].y()));
    ++res.steps;
    if (step > first_sample && (step - first_sample) % per_phase == 0) sample(state.time);
  }
  res.transverse = local.comm.max(transverse) / res.u_peak;
  res.samples = gather_to_root(mine, comm);
  if (model) {
    res.max_nu_ratio = record.global_max(local);
    res.mean_nu_ratio = record.global_mean(local);
  }
  res.final_velocity.assign(3 * static_cast<std::size_t>(metrics.num_nodes()), 0.0);
  for (int j = 0; j < local.num_owned; ++j)
    for (int c = 0; c < 3; ++c)
      res.final_velocity[3 * local.dual_node[j] + c] = state.velocity[j][c];
  MPI_Allreduce(MPI_IN_PLACE, res.final_velocity.data(),
                static_cast<int>(res.final_velocity.size()), MPI_DOUBLE, MPI_SUM, comm);
  res.wall = local.comm.max(MPI_Wtime() - t0);
  return res;
}

}  // namespace valsalva::validation
