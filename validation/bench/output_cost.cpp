// Benchmark (opt-in, not a test): what the analysis outputs cost next to a flow step (issue 7).
// A periodic n^3 hexahedral box (n = 100: 1 M nodes) with the Taylor-Green field steps through the
// scene path as `valsalva run` runs it (validation/tgv_les/tgv_les.toml without a model, central2,
// run::Simulation and its run loop; a step is timed from the end of one observer call to the start
// of the next, so it includes the loop's own per-step work); in the same run, from the observer,
// it times per call phase statistics (analysis::PhaseStatistics)
// on the whole mesh and on 2 planes, analysis::Probes::sample, a field write (velocity, pressure,
// vorticity), a checkpoint with and without the statistics arrays, and PhaseStatistics::write.
// Times are process CPU seconds (the machine is shared; wall time is printed beside), the max over
// ranks per call; ns/node is the CPU time summed over ranks per covered node. Memory: resident
// size before and after allocating the whole-mesh statistics, and the peak during a checkpoint.
// The files it writes go to OUT and are removed at the end unless --keep 1.
// Usage: [mpiexec -n R] bench_output_cost [--n 100] [--bins 20] [--steps 3] [--probes 20]
//        [--out bench-results/output_cost] [--keep 0]
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/phase_statistics.hpp"
#include "analysis/probes.hpp"
#include "core/comm.hpp"
#include "flow/operators.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
#include "run/simulation.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/scene_run.hpp"

using namespace valsalva;

namespace {

struct Args {
  int n = 100, bins = 20, steps = 3, probes = 20;
  bool keep = false;
  std::filesystem::path out = "bench-results/output_cost";
};

struct Seconds {
  double cpu = 0, wall = 0;
};

Seconds now() {
  timespec w;
  clock_gettime(CLOCK_MONOTONIC, &w);
  return {bench::cpu_seconds(), w.tv_sec + 1e-9 * w.tv_nsec};
}

// Accumulated cost of one kind of call on this rank. The barrier first, so that a collective
// call is not charged with the time its ranks wait for each other to arrive (MPI polls: CPU).
struct Cost {
  Cost(std::string w, double n) : what(std::move(w)), nodes(n) {}
  std::string what;
  double nodes;  // global nodes the call covers
  int calls = 0;
  Seconds total;
  double fastest = 1e300;  // CPU s of the cheapest call: robust when other jobs preempt a rank
  void time(const std::function<void()>& f) {
    MPI_Barrier(MPI_COMM_WORLD);
    const Seconds a = now();
    f();
    add(a, now());
  }
  void add(const Seconds& a, const Seconds& b) {
    total.cpu += b.cpu - a.cpu, total.wall += b.wall - a.wall, ++calls;
    fastest = std::min(fastest, b.cpu - a.cpu);
  }
};

// kB from /proc/self/status ("VmRSS", "VmHWM").
double status_kb(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1));
  return 0;
}

std::vector<int> union_of(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

// What is measured, set up on the run's mesh before its first step.
struct Measured {
  Measured(const run::Simulation& sim, const Args& args) {
    const auto& local = sim.local();
    const double L = 2 * std::numbers::pi;
    h = L / args.n;
    nodes = double(local.global_nodes);
    // Whole-mesh statistics: resident size before and after (zero-filled, so all pages touched).
    const analysis::PhaseStatisticsOptions so{args.bins * 0.5 * h, args.bins, 0, 1, "all"};
    const double rss0 = status_kb("VmRSS");
    all.emplace(local, so, analysis::all_owned_nodes(local));
    stats_bytes = 1024 * local.comm.sum(status_kb("VmRSS") - rss0);
    // Two planes through grid nodes, one node layer each.
    const Eigen::Vector3d mid = Eigen::Vector3d::Constant(args.n / 2 * h);
    auto plane_nodes = union_of(analysis::nodes_near_plane(local, mid, {0, 0, 1}, 0.25 * h),
                                analysis::nodes_near_plane(local, mid, {1, 0, 0}, 0.25 * h));
    plane_count = local.comm.sum(double(plane_nodes.size()));
    planes.emplace(local, analysis::PhaseStatisticsOptions{so.period, so.bins, 0, 1, "planes"},
                   std::move(plane_nodes));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> inside(0.01 * L, 0.99 * L);
    std::vector<analysis::ProbePoint> points;
    for (int p = 0; p < args.probes; ++p)
      points.push_back({fmt::format("p{}", p), {inside(random), inside(random), inside(random)}});
    probes.emplace(sim.mesh(), sim.metrics(), local, points);
    costs = {{"flow step (RK4 + Poisson)", nodes},
             {"statistics add, whole mesh", nodes},
             {"statistics add, 2 planes", plane_count},
             {fmt::format("probes sample ({} probes)", args.probes), double(args.probes)},
             {"field write u, p, vorticity", nodes},
             {"checkpoint, state only", nodes},
             {"checkpoint + statistics arrays", nodes},
             {"statistics write, 2 planes", plane_count},
             {"statistics write, whole mesh", nodes}};
  }

  // After a step: the per-step analyses on its state.
  void per_step(const flow::FlowState& state) {
    costs[1].time([&] { all->add(state.time, state.velocity, state.pressure); });
    costs[2].time([&] { planes->add(state.time, state.velocity, state.pressure); });
    for (int k = 0; k < 10; ++k) costs[3].time([&] { probes->sample(state); });
  }

  // At the end: one field write, two checkpoints, the statistics files.
  void at_end(const run::Simulation& sim, const std::filesystem::path& out) {
    const auto& local = sim.local();
    const auto& state = sim.state();
    io::FieldOutput output(sim.mesh(), sim.metrics(), local, out, "fields");
    flow::TensorField grad;
    flow::VectorField omega;
    costs[4].time([&] {
      flow::gradient(local, state.velocity, grad);
      flow::vorticity(grad, omega);
      output.write(state.time, {{"pressure", &state.pressure}},
                   {{"velocity", &state.velocity}, {"vorticity", &omega}});
    });
    io::CheckpointWriter writer(local, io::mesh_hash(sim.mesh()), out / "checkpoints");
    const double dt = 0.5 * h;
    costs[5].time([&] { writer.write(state, 1, dt); });
    hwm_before = local.comm.max(status_kb("VmHWM"));
    costs[6].time([&] {
      auto extras = all->checkpoint_arrays();
      for (auto& a : planes->checkpoint_arrays()) extras.push_back(std::move(a));
      writer.write(state, 2, dt, extras);
    });
    hwm_after = local.comm.max(status_kb("VmHWM"));
    costs[7].time([&] { planes->write(sim.mesh(), sim.metrics(), out / "statistics"); });
    costs[8].time([&] { all->write(sim.mesh(), sim.metrics(), out / "statistics"); });
  }

  double h = 0, nodes = 0, plane_count = 0, stats_bytes = 0, hwm_before = 0, hwm_after = 0;
  std::optional<analysis::PhaseStatistics> all, planes;
  std::optional<analysis::Probes> probes;
  std::vector<Cost> costs;
};

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::App app{"bench_output_cost",
                 "Cost of statistics, probes, field and checkpoint output next to a flow step, "
                 "and the statistics memory"};
  app.add_option("--n", args.n, "Cells per side of the periodic box (100: 1 M nodes)")
      ->check(bench::positive);
  app.add_option("--bins", args.bins, "Phase bins of the statistics")->check(bench::positive);
  app.add_option("--steps", args.steps, "Timed flow steps")->check(bench::positive);
  app.add_option("--probes", args.probes, "Probe points")->check(bench::positive);
  app.add_option("--out", args.out, "Folder of the files written");
  app.add_option("--keep", args.keep, "Keep the files written (else removed at the end)");
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    if (rank == 0) std::filesystem::create_directories(args.out);
    const double h = 2 * std::numbers::pi / args.n, dt = 0.5 * h;
    std::optional<Measured> m;
    Seconds last;  // the end of the previous observer call: the next step starts there
    validation::SceneRun measure;
    measure.at_start = [&](const run::Simulation& sim) {
      m.emplace(sim, args);
      MPI_Barrier(MPI_COMM_WORLD);
      last = now();
    };
    measure.observer = [&](const run::Simulation& sim, std::int64_t step) {
      MPI_Barrier(MPI_COMM_WORLD);
      // Step 1 is the warm-up: first touch and the Poisson set-up stay out of the figures.
      if (step > 1) m->costs[0].add(last, now());
      m->per_step(sim.state());
      MPI_Barrier(MPI_COMM_WORLD);
      last = now();
    };
    measure.at_end = [&](const run::Simulation& sim) { m->at_end(sim, args.out); };
    validation::run_scene_file(
        validation::case_scene("tgv_les", "tgv_les.toml"),
        {fmt::format("mesh.box.cells=[{0}, {0}, {0}]", args.n), "flow.scheme=\"central2\"",
         "les.model=\"none\"", fmt::format("time.dt={:.17g}", dt),
         fmt::format("time.end={:.17g}", (args.steps + 1) * dt), "time.land_on_output=false"},
        {}, MPI_COMM_WORLD, measure);

    const auto& costs = m->costs;
    const core::Comm comm(MPI_COMM_WORLD);
    const double step_cpu = comm.max(costs[0].total.cpu) / costs[0].calls;
    std::string table;
    for (const Cost& c : costs) {
      const double cpu = comm.max(c.total.cpu) / c.calls;
      const double wall = comm.max(c.total.wall) / c.calls;
      const double ns = 1e9 * comm.sum(c.total.cpu) / c.calls / c.nodes;
      table +=
          fmt::format("  {:<34} {:>5} {:>10.3g} {:>10.3g} {:>9.3g} {:>9.3g} {:>10.4g}\n", c.what,
                      c.calls, cpu, comm.max(c.fastest), wall, 100 * cpu / step_cpu, ns);
    }
    if (rank == 0) {
      std::uintmax_t bytes = 0;
      for (const auto& f : std::filesystem::recursive_directory_iterator(args.out))
        if (f.is_regular_file()) bytes += f.file_size();
      fmt::print(
          "bench_output_cost: {}^3 periodic hexahedra, {:.0f} nodes, {} rank(s); {}\n  {} timed "
          "steps of dt {:.4g} through run::Simulation; statistics {} bins; planes {:.0f} "
          "nodes; {} probes\n"
          "  {:<34} {:>5} {:>10} {:>10} {:>9} {:>9} {:>10}\n{}",
          args.n, m->nodes, size, bench::machine(), costs[0].calls, dt, args.bins, m->plane_count,
          args.probes, "per call", "calls", "cpu s", "min cpu s", "wall s", "% step", "ns/node",
          table);
      fmt::print(
          "  (cpu s: mean over calls; % step: of the mean step; ns/node: CPU ns summed over ranks "
          "per covered node, per probe for the probes)\n"
          "  memory: whole-mesh statistics {:.1f} MB resident over all ranks = {:.1f} B per "
          "node and bin (documented 88)\n          = {:.1f} MB per phase bin for {:.0f} nodes; "
          "peak resident per rank {:.0f} MB before the checkpoint with statistics, {:.0f} MB "
          "after\n  files written: {:.1f} MB in {}{}\n",
          m->stats_bytes / 1e6, m->stats_bytes / m->nodes / args.bins,
          m->stats_bytes / args.bins / 1e6, m->nodes, m->hwm_before / 1024, m->hwm_after / 1024,
          bytes / 1e6, args.out.string(), args.keep ? "" : " (removed)");
      if (!args.keep) std::filesystem::remove_all(args.out);
    }
  });
}
