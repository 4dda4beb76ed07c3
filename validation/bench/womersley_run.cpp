// A Womersley pipe run; see womersley_run.hpp.
#include "validation/bench/womersley_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"
#include "flow/womersley.hpp"
#include "les/subgrid_viscosity.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/extruded_pipe_generator.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/pipe_generator.hpp"

namespace valsalva::validation {

namespace {

constexpr double kDensity = 1100, kViscosity = 3.6e-3, kPeriod = 1.0;

}  // namespace

double womersley_radius(double womersley) {
  return womersley * std::sqrt(kViscosity / kDensity / (2 * std::numbers::pi / kPeriod));
}

mesh::Mesh womersley_mesh(const WomersleySetup& setup, MPI_Comm comm) {
  const double R = womersley_radius(setup.womersley), L = setup.length_in_diameters * 2 * R;
  const double size = setup.mesh_size_factor * 2 * R / setup.nodes_per_diameter;
  if (setup.extruded) {
    mesh::ExtrudedPipeSpec spec;
    spec.radius = R, spec.length = L, spec.target_size = size;
    spec.layer_height = setup.layer_height * size;
    spec.grading = setup.grading;
    for (double* d : {&spec.grading.wall_size, &spec.grading.wall_distance,
                      &spec.grading.layer_first, &spec.grading.layer_thickness})
      *d *= size;
    return mesh::generate_extruded_pipe_mesh(spec, comm);
  }
  auto options = setup.mesh;
  options.wall_size *= size;
  options.wall_distance *= size;
  return mesh::generate_pipe_mesh(R, L, size, options);
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

  const auto mesh = womersley_mesh(setup, comm);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, comm);
  res.nodes = local.global_nodes;

  auto inlet = flow::boundary_spec("inlet", flow::BoundaryType::inlet);
  inlet.profile = flow::InletProfile::womersley;
  inlet.flow_rate.kind = flow::Waveform::Kind::sine;
  inlet.flow_rate.mean = q0;
  inlet.flow_rate.amplitude = q0;
  inlet.flow_rate.period = kPeriod;
  inlet.unscaled_profile = setup.unscaled_inlet;
  auto bc = std::make_shared<flow::BoundaryConditions>(
      local,
      std::vector<flow::BoundarySpec>{inlet, flow::boundary_spec("wall", flow::BoundaryType::wall),
                                      flow::boundary_spec("outlet", setup.outlet)},
      nu);
  const auto exact = flow::Womersley::from_sine(R, nu, q0, q0, kPeriod, 0.0);
  res.exact = exact;

  flow::ProjectionOptions options;
  options.density = kDensity;
  options.viscosity = nu;
  options.poisson.tolerance = setup.poisson_tolerance;
  options.boundary = bc;
  options.stiffness_viscous = setup.stiffness_viscous;
  options.pressure_damping = setup.pressure_damping;
  if (bc->has_pressure_outlet()) options.poisson.dirichlet = bc->pressure_dirichlet();
  // LES: the model, with running max and sum of nu_sgs / nu over owned nodes and stages.
  std::unique_ptr<les::SubgridViscosity> model;
  NuSgsRecord record;
  double nu_first = -1, nu_interior = 0;
  if (setup.les_model != "none") {
    model = std::make_unique<les::SubgridViscosity>(setup.les_model, std::nullopt, local.h);
    // Every stage (les.update = "stage"): the largest nu_sgs the model produces anywhere.
    options.subgrid_viscosity = [&](int, const flow::TensorField& g, flow::ScalarField& nu_sgs) {
      (*model)(g, nu_sgs);
      record.add(local, nu_sgs, nu);
      for (int i = 0; i < local.num_owned; ++i)
        if (std::abs(local.position[i].z() - L / 2) <= L / 6)
          nu_interior = std::max(nu_interior, nu_sgs[i] / nu);
      if (nu_first < 0) nu_first = record.max;
    };
  }
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));

  // Exact initial state: u(r, 0) e_z and p = -rho G(0) (z - L), zero at the outlet.
  auto radius_of = [&](const Eigen::Vector3d& x) { return std::min(std::hypot(x.x(), x.y()), R); };
  flow::FlowState state;
  const int n = local.num_local();
  state.velocity.assign(n, Eigen::Vector3d::Zero());
  state.pressure.assign(n, 0.0);
  for (int j = 0; j < n; ++j) {
    const auto& x = local.position[j];
    state.velocity[j].z() = exact.velocity(radius_of(x), 0.0);
    state.pressure[j] = -kDensity * exact.pressure_gradient(0.0) * (x.z() - L);
  }
  bc->impose_pressure(state.pressure);
  bc->hold_outlets(state.velocity);
  bc->impose(state.velocity, 0.0);

  const auto steps = phase_steps(exact, kPeriod, setup.phases, setup.cfl, h);
  res.u_peak = steps.u_peak, res.dt = steps.dt;
  const int per_phase = steps.per_phase;
  const double dt = steps.dt;

  const auto weights = flow::laplacian_weights(local);
  std::vector<double> scratch;
  auto sample = [&](double t) {
    PhaseSample s;
    s.time = t;
    double e2 = 0, vol = 0;
    std::vector<double> mine;
    double q = 0, qe = 0, region = 0;
    for (int j = 0; j < local.num_owned; ++j) {
      const auto& x = local.position[j];
      if (std::abs(x.z() - L / 2) <= L / 6) {
        q += local.volume[j] * state.velocity[j].z();
        qe += local.volume[j] * exact.velocity(radius_of(x), t);
        region += local.volume[j];
      }
      const bool slab = std::abs(x.z() - L / 2) <= h / 2;
      if (!slab && !setup.sample_whole_pipe) continue;
      const double r = radius_of(x), ue = exact.velocity(r, t);
      const auto& u = state.velocity[j];
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
    s.flow_rate = inlet.flow_rate(t);
    const auto all = gather_to_root(mine, comm);
    for (std::size_t i = 0; i + 7 < all.size(); i += 8) {
      s.x.push_back(all[i]), s.y.push_back(all[i + 1]), s.z.push_back(all[i + 2]);
      s.r.push_back(all[i + 3]), s.u.push_back(all[i + 4]), s.exact.push_back(all[i + 5]);
      s.ux.push_back(all[i + 6]), s.uy.push_back(all[i + 7]);
    }
    // The fixed step must stay inside the RK4 stability region (flow/run_diagnostics.hpp).
    const double limit =
        1.0 / flow::stability_rates(local, weights, nu, state.velocity, scratch).stability;
    if (dt > limit)
      throw std::runtime_error(fmt::format(
          "womersley: dt {:.4g} s beyond the RK4 stability limit {:.4g} s at t = {:.4g} s", dt,
          limit, t));
    return s;
  };

  const int total = per_phase * setup.phases * (setup.sample_period + 1);
  const int first_sample = per_phase * setup.phases * setup.sample_period;
  for (int step = 1; step <= total; ++step) {
    if (setup.max_steps > 0 && step > setup.max_steps) break;
    const auto report = solver.step(state, dt);
    res.max_divergence = std::max(res.max_divergence, report.max_divergence);
    // |div u| stays below u_peak / h (~300 1/s at D/20) in a sane run; 1e6 is a blow-up.
    if (!std::isfinite(report.max_divergence) || report.max_divergence > 1e6)
      throw std::runtime_error(
          fmt::format("womersley: the run blew up at step {} (t = {:.4g} s, "
                      "max |div u| {:.3g} 1/s)",
                      step, state.time, report.max_divergence));
    ++res.steps;
    if (setup.max_steps == 0 && step > first_sample && (step - first_sample) % per_phase == 0)
      res.phases.push_back(sample(state.time));
  }
  for (const auto& s : res.phases) {
    res.max_error = std::max(res.max_error, s.max_error);
    res.l2_error = std::max(res.l2_error, s.l2_error);
    res.transverse = std::max(res.transverse, s.transverse);
  }
  if (model) {
    res.max_nu_ratio = record.global_max(local);
    res.mean_nu_ratio = record.global_mean(local);
    res.first_stage_nu_ratio = local.comm.max(nu_first);
    res.interior_nu_ratio = local.comm.max(nu_interior);
  }
  // Final fields by dual node, on every rank (owned values summed over the ranks).
  const auto nodes = static_cast<std::size_t>(metrics.num_nodes());
  res.final_velocity.assign(3 * nodes, 0.0);
  res.final_pressure.assign(nodes, 0.0);
  for (int j = 0; j < local.num_owned; ++j) {
    res.final_pressure[local.dual_node[j]] = state.pressure[j];
    for (int c = 0; c < 3; ++c)
      res.final_velocity[3 * local.dual_node[j] + c] = state.velocity[j][c];
  }
  for (auto* field : {&res.final_velocity, &res.final_pressure})
    MPI_Allreduce(MPI_IN_PLACE, field->data(), static_cast<int>(field->size()), MPI_DOUBLE, MPI_SUM,
                  comm);
  res.wall = local.comm.max(MPI_Wtime() - t0);
  return res;
}

}  // namespace valsalva::validation
