// Benchmark (opt-in, not a test): what the leaflet contact costs in a valve scene. The scene
// (default scenes/valve_quick.toml) runs --steps steps through run::Simulation; then, at the
// markers' positions of the last step, the first structure's forces (internal + tether +
// contact: ImmersedBody::forces, what every coupling stage evaluates) are timed --repetitions
// times, and the contact search's work is counted (ContactSummary: slave Gauss points,
// closest-point projections per point, Newton iterations per projection). With the per-stage
// coupling a step evaluates the forces four times: 4 x that time over the step's CPU time is the
// share of the step they take. CPU times of this process (the machine is shared).
//   [mpiexec -n R] bench_contact_cost [--scene scenes/valve_quick.toml] [--steps 10]
//                                     [--repetitions 20] [--set KEY=VALUE ...]
#include <fmt/format.h>
#include <mpi.h>

#include <string>
#include <vector>

#include "ibm/immersed_structure.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/scene_run.hpp"

namespace {

namespace v = valsalva::validation;

struct Args {
  std::string scene = "scenes/valve_quick.toml";
  int steps = 10;
  int repetitions = 20;
  std::vector<std::string> settings;
};

}  // namespace

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  Args args;
  bench::App app{"bench_contact_cost",
                 "CPU time of the leaflet forces with contact, and the contact search's work, at "
                 "the state a valve scene reaches after some steps"};
  app.add_option("--scene", args.scene, "Scene file with a [structure.<name>] table with contact");
  app.add_option("--steps", args.steps, "Steps before the measurement (time.max_steps)")
      ->check(bench::positive);
  app.add_option("--repetitions", args.repetitions, "Timed force evaluations")
      ->check(bench::positive);
  app.add_option("--set", args.settings, "Scene override KEY=VALUE (repeatable)");
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    if (rank == 0)
      fmt::print("bench_contact_cost: {}, {} steps, {} rank(s), {}\n", args.scene, args.steps, size,
                 bench::machine());
    std::vector<std::string> overrides = args.settings;
    overrides.push_back(fmt::format("time.max_steps={}", args.steps));
    double start = 0;
    v::SceneRun measure;
    measure.at_start = [&](const valsalva::run::Simulation&) { start = bench::cpu_seconds(); };
    measure.at_end = [&](const valsalva::run::Simulation& sim) {
      const double per_step = (bench::cpu_seconds() - start) / args.steps;
      if (!sim.immersed() || sim.immersed()->num_bodies() == 0)
        throw std::runtime_error(args.scene + " has no immersed structure");
      const auto& ib = *sim.immersed();
      const auto& body = ib.body(0);
      if (!body.has_contact())
        throw std::runtime_error(args.scene + ": the structure has no contact");
      const Eigen::Matrix3Xd x = ib.body_positions(0);
      Eigen::Matrix3Xd f(3, x.cols());
      const double t0 = bench::cpu_seconds();
      for (int r = 0; r < args.repetitions; ++r) body.forces(x, f);
      const double per_eval = (bench::cpu_seconds() - t0) / args.repetitions;
      const auto s = body.contact_summary(x);
      if (rank != 0) return;
      fmt::print(
          "state after {} steps: t = {:.6g} s, smallest gap {:.4g} m, contact force {:.4g} N\n",
          args.steps, sim.state().time, s.min_gap, s.force);
      fmt::print(
          "contact search: {} slave points, {:.2f} projections per point, {:.2f} Newton "
          "iterations per projection\n",
          s.slave_points, double(s.projections) / double(std::max(1L, s.slave_points)),
          double(s.newton_iterations) / double(std::max(1L, s.projections)));
      fmt::print(
          "CPU per step {:.4f} s; leaflet forces with contact {:.4f} s per evaluation, "
          "4 per step: {:.1f} % of the step\n",
          per_step, per_eval, 100 * 4 * per_eval / per_step);
    };
    v::run_scene_file(args.scene, overrides, "", MPI_COMM_WORLD, measure);
  });
}
