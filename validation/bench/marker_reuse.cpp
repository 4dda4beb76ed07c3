// Benchmark (opt-in, not a test): what keeping the immersed-boundary kernel supports across RK
// stages and steps (immersed.reuse_distance, ibm/dirac_transfer.hpp) saves on a scene users run.
// The scene (default scenes/flap_channel.toml) runs --steps steps through run::Simulation, once
// per --reuse value, in one process: CPU seconds per step, the share of them spent locating
// markers (DiracTransfer::counts: locate and relocate), the fraction of marker locations that
// rebuilt a support, and the largest difference of the marker positions from the first run's
// (what the lag of the kernel costs in accuracy, against the marker displacement itself).
// CPU times of this process (the machine is shared): ratios within one run are the figures.
//   [mpiexec -n R] bench_marker_reuse [--scene scenes/flap_channel.toml] [--steps 200]
//                                     [--reuse 0,0.05,0.1,0.2] [--set KEY=VALUE ...]
#include <fmt/format.h>
#include <mpi.h>

#include <ctime>
#include <string>
#include <vector>

#include "ibm/immersed_structure.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/scene_run.hpp"

namespace {

namespace v = valsalva::validation;

struct Args {
  std::string scene = "scenes/flap_channel.toml";
  int steps = 200;
  std::vector<double> reuse{0, 0.05, 0.1, 0.2};
  std::vector<std::string> settings;
};

struct Measured {
  double cpu_per_step = 0, locate_share = 0, rebuilt_fraction = 0;
  Eigen::Matrix3Xd start, end;  // marker positions
};

Measured run_once(const Args& args, double reuse) {
  std::vector<std::string> overrides = args.settings;
  overrides.push_back(fmt::format("time.max_steps={}", args.steps));
  overrides.push_back(fmt::format("immersed.reuse_distance={}", reuse));
  Measured m;
  std::clock_t start = 0;
  v::SceneRun measure;
  measure.at_start = [&](const valsalva::run::Simulation& sim) {
    if (!sim.immersed()) throw std::runtime_error(args.scene + " has no immersed structure");
    m.start = sim.immersed()->positions();
    start = std::clock();
  };
  measure.at_end = [&](const valsalva::run::Simulation& sim) {
    const double cpu = double(std::clock() - start) / CLOCKS_PER_SEC;
    const auto& ib = *sim.immersed();
    const auto& c = ib.transfer().counts();
    const auto& comm = sim.local().comm;
    m.cpu_per_step = comm.max(cpu) / args.steps;
    m.locate_share = comm.max(c.cpu_seconds) / comm.max(cpu);
    m.rebuilt_fraction = double(c.rebuilt) / double(std::max<std::int64_t>(c.markers, 1));
    m.end = ib.positions();
  };
  v::run_scene_file(args.scene, overrides, "", MPI_COMM_WORLD, measure);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  Args args;
  bench::App app{"bench_marker_reuse",
                 "CPU time per step, location share and marker-position change of a scene with "
                 "immersed structures for several immersed.reuse_distance values"};
  app.add_option("--scene", args.scene, "Scene file with [structure.<name>] tables");
  app.add_option("--steps", args.steps, "Steps per run (time.max_steps)")->check(bench::positive);
  app.add_option("--reuse", args.reuse, "immersed.reuse_distance values (comma-separated)")
      ->delimiter(',')
      ->check(bench::non_negative);
  app.add_option("--set", args.settings, "Scene override KEY=VALUE (repeatable)");
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    if (rank == 0)
      fmt::print("bench_marker_reuse: {}, {} steps, {} rank(s), {}\n", args.scene, args.steps, size,
                 bench::machine());
    std::vector<Measured> runs;
    for (double r : args.reuse) runs.push_back(run_once(args, r));
    if (rank != 0) return;
    const double moved = (runs[0].end - runs[0].start).colwise().norm().maxCoeff();
    fmt::print("{:>8} {:>12} {:>10} {:>14} {:>10} {:>22}\n", "reuse", "CPU s/step", "vs first",
               "locate share", "rebuilt", "max |dX - dX_first|");
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const double diff = (runs[k].end - runs[0].end).colwise().norm().maxCoeff();
      fmt::print("{:>8g} {:>12.4f} {:>10.3f} {:>13.1f}% {:>9.1f}% {:>12.3e} ({:.2e} of {:.3e} m)\n",
                 args.reuse[k], runs[k].cpu_per_step, runs[k].cpu_per_step / runs[0].cpu_per_step,
                 100 * runs[k].locate_share, 100 * runs[k].rebuilt_fraction, diff,
                 moved > 0 ? diff / moved : 0.0, moved);
    }
  });
}
