// A fixed-dt 3D Taylor-Green run through flow::RunLoop; see time_order_run.hpp.
#include "validation/time_order/time_order_run.hpp"

#include <cmath>
#include <limits>

#include "flow/run_loop.hpp"
#include "validation/bench/bench_util.hpp"

namespace valsalva::validation {

using bench::cpu_seconds;

std::string TimeVariant::name() const {
  return flow::time_scheme_name(scheme) + (project_stages ? "+project_stages" : "");
}

TimeOrderRun run_time_order(const TimeOrderRunSpec& spec, const TgvBox& box) {
  flow::RunOptions o;
  o.projection.density = 1;
  o.projection.viscosity = 1.0 / 1600;
  o.projection.poisson.tolerance = spec.poisson_tolerance;
  o.projection.time_scheme = spec.variant.scheme;
  o.projection.project_stages = spec.variant.project_stages;
  o.time.end = spec.t_end;
  o.time.dt = spec.t_end / spec.steps;
  o.initial = {"taylor_green_3d", spec.velocity, 1.0};
  o.output.print = false;
  o.output.log_every = std::numeric_limits<int>::max();  // no log lines but the last
  flow::RunLoop loop(box.mesh, box.metrics, box.local, o);
  const double cpu0 = cpu_seconds();
  const auto summary = loop.run();
  TimeOrderRun r;
  r.cpu_seconds = box.local.comm.sum(cpu_seconds() - cpu0);
  r.wall_seconds = summary.wall_seconds;
  r.dt = o.time.dt;
  r.steps = static_cast<int>(summary.steps);
  r.max_poisson_iterations = summary.max_poisson_iterations;
  r.velocity = loop.state().velocity;
  return r;
}

double velocity_l2_difference(const flow::LocalMesh& local, const flow::VectorField& a,
                              const flow::VectorField& b) {
  double volume = 0, sum = 0;
  for (int j = 0; j < local.num_owned; ++j) {
    volume += local.volume[j];
    sum += local.volume[j] * (a[j] - b[j]).squaredNorm();
  }
  return std::sqrt(local.comm.sum(sum) / local.comm.sum(volume));
}

}  // namespace valsalva::validation
