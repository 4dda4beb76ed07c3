// Taylor-Green vortex run and error measurement; see tgv_run.hpp.
#include "validation/taylor_green/tgv_run.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "io/box_generator.hpp"

namespace valsalva::validation {

namespace {

struct Exact {
  double nu, rho;
  Eigen::Vector3d velocity(const Eigen::Vector3d& x, double t) const {
    const double f = std::exp(-2 * nu * t);
    return {std::sin(x.x()) * std::cos(x.y()) * f, -std::cos(x.x()) * std::sin(x.y()) * f, 0.0};
  }
  double pressure(const Eigen::Vector3d& x, double t) const {
    const double f = std::exp(-2 * nu * t);
    return rho / 4 * (std::cos(2 * x.x()) + std::cos(2 * x.y())) * f * f;
  }
};

}  // namespace

TgvResult run_taylor_green(const TgvSpec& spec, MPI_Comm comm) {
  const auto start = std::chrono::steady_clock::now();
  const double two_pi = 2 * std::numbers::pi;
  const double h = two_pi / spec.n;
  io::BoxSpec box;
  box.cell_type = spec.cell_type;
  box.perturbation = spec.perturbation;
  box.cells = {spec.n, spec.n, spec.nz};
  box.length = Eigen::Vector3d(two_pi, two_pi, spec.nz * h);
  box.periodic = {true, true, true};
  const auto mesh = io::generate_box(box);
  const auto metrics = flow::compute_dual_metrics(mesh);
  const auto local = flow::distribute(mesh, metrics, comm, {2, "metis"});

  flow::ProjectionOptions options;
  options.density = 1.0;
  options.viscosity = 1.0 / spec.reynolds;
  options.poisson = spec.poisson;
  const Exact exact{options.viscosity, options.density};
  flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));

  flow::FlowState state;
  for (int i = 0; i < local.num_local(); ++i) {
    state.velocity.push_back(exact.velocity(local.position[i], 0.0));
    state.pressure.push_back(exact.pressure(local.position[i], 0.0));
  }
  TgvResult r;
  r.n = spec.n;
  r.h = h;
  r.nodes = local.global_nodes;
  r.steps = static_cast<int>(std::ceil(spec.t_end / (spec.cfl * h) - 1e-9));
  r.dt = spec.t_end / r.steps;
  for (int s = 0; s < r.steps; ++s) {
    const auto report = solver.step(state, r.dt);
    r.max_poisson_iterations = std::max(r.max_poisson_iterations, report.poisson.iterations);
    r.max_divergence = std::max(r.max_divergence, report.max_divergence);
  }

  const auto& c = local.comm;
  double volume = 0, p_mean = 0, pe_mean = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    volume += local.volume[i];
    p_mean += local.volume[i] * state.pressure[i];
    pe_mean += local.volume[i] * exact.pressure(local.position[i], state.time);
  }
  volume = c.sum(volume);
  p_mean = c.sum(p_mean) / volume;
  pe_mean = c.sum(pe_mean) / volume;
  double e2 = 0, einf = 0, ep = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    const auto& x = local.position[i];
    const double du = (state.velocity[i] - exact.velocity(x, state.time)).norm();
    e2 += local.volume[i] * du * du;
    einf = std::max(einf, du);
    ep += local.volume[i] *
          std::pow(state.pressure[i] - p_mean - (exact.pressure(x, state.time) - pe_mean), 2);
  }
  r.velocity_l2 = std::sqrt(c.sum(e2) / volume);
  r.velocity_linf = c.max(einf);
  r.pressure_l2 = std::sqrt(c.sum(ep) / volume);
  r.wall_seconds =
      c.max(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return r;
}

}  // namespace valsalva::validation
