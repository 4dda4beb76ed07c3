// A fixed-dt 3D Taylor-Green run through run::Simulation; see time_order_run.hpp.
#include "validation/time_order/time_order_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/comm.hpp"
#include "run/simulation.hpp"
#include "scene/scene.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

std::string TimeVariant::name() const {
  return flow::time_scheme_name(scheme) + (project_stages ? "+project_stages" : "");
}

TimeOrderRun run_time_order(const TimeOrderRunSpec& spec, const std::filesystem::path& run_dir,
                            MPI_Comm comm) {
  const double dt = spec.t_end / spec.steps;
  const auto scene = scene::load_scene(
      case_scene("time_order", "time_order.toml"),
      {fmt::format("mesh.box.cells=[{0}, {0}, {0}]", spec.cells),
       fmt::format("time.end={:.17g}", spec.t_end), fmt::format("time.dt={:.17g}", dt),
       fmt::format("time.scheme=\"{}\"", flow::time_scheme_name(spec.variant.scheme)),
       fmt::format("time.project_stages={}", spec.variant.project_stages ? "true" : "false"),
       fmt::format("initial.taylor_green.velocity={:.17g}", spec.velocity)});
  run::Simulation sim(scene, level_request(run_dir), comm);
  const double cpu0 = bench::cpu_seconds();
  const auto result = sim.run();
  const auto& local = sim.local();
  TimeOrderRun r;
  r.cpu_seconds = local.comm.sum(bench::cpu_seconds() - cpu0);
  r.wall_seconds = result.summary.wall_seconds;
  r.dt = dt;
  r.steps = static_cast<int>(result.summary.steps);
  r.max_poisson_iterations = result.summary.max_poisson_iterations;
  for (int j = 0; j < local.num_owned; ++j) {
    r.velocity.push_back(sim.state().velocity[j]);
    r.volume.push_back(local.volume[j]);
    r.position.push_back(local.position[j]);
  }
  return r;
}

double velocity_l2_difference(const TimeOrderRun& a, const TimeOrderRun* b, MPI_Comm comm) {
  if (b && (b->position.size() != a.position.size() ||
            !std::equal(a.position.begin(), a.position.end(), b->position.begin())))
    throw std::logic_error(
        "validation::time_order: two runs of one mesh own different nodes (partition changed)");
  double volume = 0, sum = 0;
  for (std::size_t j = 0; j < a.velocity.size(); ++j) {
    volume += a.volume[j];
    sum += a.volume[j] * (b ? (a.velocity[j] - b->velocity[j]) : a.velocity[j]).squaredNorm();
  }
  const core::Comm c(comm);
  return std::sqrt(c.sum(sum) / c.sum(volume));
}

}  // namespace valsalva::validation
