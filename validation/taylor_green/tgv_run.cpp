// Taylor-Green vortex run and error measurement; see tgv_run.hpp.
#include "validation/taylor_green/tgv_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "core/comm.hpp"
#include "flow/convection_scheme.hpp"
#include "flow/initial_condition.hpp"
#include "flow/operators.hpp"
#include "flow/operators_order4.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

struct TgvMesh {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
};

TgvMesh build_mesh(const TgvSpec& spec, MPI_Comm comm) {
  const double two_pi = 2 * std::numbers::pi;
  const double h = two_pi / spec.n;
  mesh::BoxSpec box;
  box.cell_type = mesh::parse_box_cell_type(spec.cell_type);
  box.perturbation = spec.perturbation;
  box.cells = {spec.n, spec.n, spec.nz};
  box.length = Eigen::Vector3d(two_pi, two_pi, spec.nz * h);
  box.periodic = {true, true, true};
  TgvMesh m;
  m.mesh = mesh::generate_box(box);
  m.metrics = mesh::compute_dual_metrics(m.mesh);
  m.local = mesh::distribute(m.mesh, m.metrics, comm, {2, mesh::PartitionMethod::metis});
  return m;
}

flow::TaylorGreen exact_solution(const TgvSpec& spec) {
  return {1.0, 1.0, 1.0 / spec.reynolds, 1.0};  // U0 = L = rho = 1, nu = 1/Re (0 if Re = inf)
}

double mean_kinetic_energy(const mesh::LocalMesh& local, const flow::VectorField& u) {
  double e = 0, v = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    e += 0.5 * local.volume[i] * u[i].squaredNorm();
    v += local.volume[i];
  }
  return local.comm.sum(e) / local.comm.sum(v);
}

// sqrt(sum V |a - b|^2 / sum V) over owned nodes.
double l2_difference(const mesh::LocalMesh& local, const flow::VectorField& a,
                     const flow::VectorField& b) {
  double e = 0, v = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    e += local.volume[i] * (a[i] - b[i]).squaredNorm();
    v += local.volume[i];
  }
  return std::sqrt(local.comm.sum(e) / local.comm.sum(v));
}

// The level as scene overrides of validation/taylor_green/taylor_green.toml.
std::vector<std::string> level_overrides(const TgvSpec& spec, double dt) {
  const double h = 2 * std::numbers::pi / spec.n;
  const double mu = std::isfinite(spec.reynolds) ? 1.0 / spec.reynolds : 0.0;  // rho = U0 = L = 1
  return {
      fmt::format("mesh.box.cells=[{}, {}, {}]", spec.n, spec.n, spec.nz),
      fmt::format("mesh.box.length=[{:.17g}, {:.17g}, {:.17g}]", 2 * std::numbers::pi,
                  2 * std::numbers::pi, spec.nz * h),
      fmt::format("mesh.box.cell_type={}", spec.cell_type),
      fmt::format("mesh.box.perturbation={:.17g}", spec.perturbation),
      fmt::format("flow.viscosity={:.17g}", mu),
      fmt::format("flow.scheme={}", spec.scheme),
      fmt::format("flow.fourth_order_operators={}", spec.fourth_order_operators),
      fmt::format("flow.viscous_weights={}", spec.stiffness_viscous ? "stiffness" : "two_point"),
      fmt::format("poisson.tolerance={:.17g}", spec.poisson.tolerance),
      fmt::format("poisson.max_iterations={}", spec.poisson.max_iterations),
      fmt::format("time.end={:.17g}", spec.t_end),
      fmt::format("time.dt={:.17g}", dt)};
}

}  // namespace

TgvResult run_taylor_green(const TgvSpec& spec, MPI_Comm comm,
                           const std::filesystem::path& run_dir) {
  const auto start = std::chrono::steady_clock::now();
  const auto exact = exact_solution(spec);
  TgvResult r;
  r.n = spec.n;
  r.h = 2 * std::numbers::pi / spec.n;
  double dt = spec.cfl * r.h;
  if (spec.dt_max > 0) dt = std::min(dt, spec.dt_max);
  r.steps = static_cast<int>(std::ceil(spec.t_end / dt - 1e-9));
  r.dt = spec.t_end / r.steps;

  SceneRun measure;
  r.kinetic_energy.reserve(r.steps + 1);
  auto energy = [&](const run::Simulation& sim) {
    r.kinetic_energy.push_back(mean_kinetic_energy(sim.local(), sim.state().velocity));
  };
  measure.at_start = energy;
  measure.observer = [&](const run::Simulation& sim, std::int64_t) { energy(sim); };
  measure.at_end = [&](const run::Simulation& sim) {
    const auto& local = sim.local();
    const auto& state = sim.state();
    r.nodes = local.global_nodes;
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
  };
  const auto result = run_scene_file(case_scene("taylor_green", "taylor_green.toml"),
                                     level_overrides(spec, r.dt), run_dir, comm, measure);
  r.max_poisson_iterations = result.summary.max_poisson_iterations;
  r.max_divergence = result.summary.max_divergence;
  r.wall_seconds = core::Comm(comm).max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return r;
}

TgvSpec fourth_order_spec(const std::string& cell_type, double perturbation, int n) {
  TgvSpec spec;
  spec.cell_type = cell_type;
  spec.perturbation = perturbation;
  spec.n = n;
  spec.scheme = "central4";
  spec.fourth_order_operators = true;
  spec.cfl = 0.1;
  // Tetrahedra: a spatial error ~100x the hexahedra's, so a 4x larger dt.
  spec.dt_max = (cell_type == "hexa" ? 0.0125 : 0.05) * std::pow(16.0 / n, 2);
  return spec;
}

TgvTermErrors taylor_green_term_errors(const TgvSpec& spec, MPI_Comm comm) {
  const TgvMesh m = build_mesh(spec, comm);
  const auto& local = m.local;
  const auto exact = exact_solution(spec);
  const int n = local.num_local();
  flow::VectorField u(n), conv, conv_exact(n), visc, visc_exact(n), grad_p, grad_p_exact(n);
  flow::ScalarField p(n), div;
  flow::TensorField grad_u;
  for (int i = 0; i < n; ++i) {
    const auto& x = local.position[i];
    u[i] = exact.velocity(x, 0.0);
    p[i] = exact.pressure(x, 0.0);
    // For the TGV: div(u u) = (u.grad) u = -grad p / rho, lap u = -2 u / L^2.
    grad_p_exact[i] = Eigen::Vector3d(-0.5 * std::sin(2 * x.x()), -0.5 * std::sin(2 * x.y()), 0);
    conv_exact[i] = -grad_p_exact[i];
    visc_exact[i] = -2 * exact.nu * u[i];
  }
  flow::make_convection_scheme(flow::parse_convection_kind(spec.scheme), local)->apply(u, conv);
  flow::gradient(local, u, grad_u);
  const auto poisson_weights = flow::poisson_weights(m.mesh, m.metrics, local);
  if (spec.fourth_order_operators) {
    flow::Order4Operators order4(local, poisson_weights);
    order4.viscous(exact.nu, u, grad_u, visc);
    order4.gradient(p, grad_p);
    order4.divergence(u, div);
  } else {
    if (spec.stiffness_viscous)
      flow::viscous(local, poisson_weights, exact.nu, u, grad_u, visc, false);
    else
      flow::viscous(local, flow::laplacian_weights(local), exact.nu, u, grad_u, visc);
    flow::gradient(local, p, grad_p);
    flow::divergence(local, u, div);
  }
  double d2 = 0, volume = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    d2 += local.volume[i] * div[i] * div[i];
    volume += local.volume[i];
  }
  return {l2_difference(local, conv, conv_exact), l2_difference(local, visc, visc_exact),
          l2_difference(local, grad_p, grad_p_exact),
          std::sqrt(local.comm.sum(d2) / local.comm.sum(volume))};
}

}  // namespace valsalva::validation
