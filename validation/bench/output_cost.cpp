// Benchmark (opt-in, not a test): what the analysis outputs cost next to a flow step (issue 7).
// A periodic n^3 hexahedral box (n = 100: 1 M nodes) with the Taylor-Green field steps with
// flow::ProjectionRK4; in the same run it times, per call, phase statistics (io::PhaseStatistics)
// on the whole mesh and on 2 planes, io::Probes::sample, a field write (velocity, pressure,
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
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/operators.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/run_diagnostics.hpp"
#include "io/box_generator.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
#include "io/phase_statistics.hpp"
#include "io/probes.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"

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
    const Seconds b = now();
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
    const double L = 2 * std::numbers::pi, h = L / args.n;
    io::BoxSpec spec;
    spec.cells = {args.n, args.n, args.n};
    spec.length = Eigen::Vector3d::Constant(L);
    spec.periodic = {true, true, true};
    const auto mesh = io::generate_box(spec);
    const auto metrics = flow::compute_dual_metrics(mesh);
    const auto local = flow::distribute(mesh, metrics, MPI_COMM_WORLD);
    flow::ProjectionOptions options;
    options.viscosity = 1.0 / 1600;
    options.poisson.tolerance = 1e-8;
    flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));
    flow::FlowState state;
    for (const auto& x : local.position) {
      state.velocity.push_back({std::sin(x.x()) * std::cos(x.y()) * std::cos(x.z()),
                                -std::cos(x.x()) * std::sin(x.y()) * std::cos(x.z()), 0.0});
      state.pressure.push_back((std::cos(2 * x.x()) + std::cos(2 * x.y())) *
                               (std::cos(2 * x.z()) + 2) / 16);
    }
    const double dt = 0.5 * h, nodes = double(local.global_nodes);
    if (rank == 0) std::filesystem::create_directories(args.out);

    // Whole-mesh statistics: resident size before and after (zero-filled, so all pages touched).
    const io::PhaseStatisticsOptions so{args.bins * dt, args.bins, 0, 1, "all"};
    const double rss0 = status_kb("VmRSS");
    io::PhaseStatistics all(local, so, io::all_owned_nodes(local));
    const double rss1 = status_kb("VmRSS");
    // Two planes through grid nodes, one node layer each.
    const Eigen::Vector3d mid = Eigen::Vector3d::Constant(args.n / 2 * h);
    auto plane_nodes = union_of(io::nodes_near_plane(local, mid, {0, 0, 1}, 0.25 * h),
                                io::nodes_near_plane(local, mid, {1, 0, 0}, 0.25 * h));
    const double plane_count = local.comm.sum(double(plane_nodes.size()));
    io::PhaseStatistics planes(local, {so.period, so.bins, 0, 1, "planes"}, std::move(plane_nodes));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> inside(0.01 * L, 0.99 * L);
    std::vector<io::ProbePoint> points;
    for (int p = 0; p < args.probes; ++p)
      points.push_back({fmt::format("p{}", p), {inside(random), inside(random), inside(random)}});
    const io::Probes probes(mesh, metrics, local, points);

    Cost step{"flow step (RK4 + Poisson)", nodes}, add_all{"statistics add, whole mesh", nodes},
        add_planes{"statistics add, 2 planes", plane_count},
        sample{fmt::format("probes sample ({} probes)", args.probes), double(args.probes)},
        fields{"field write u, p, vorticity", nodes}, ckpt{"checkpoint, state only", nodes},
        ckpt_stats{"checkpoint + statistics arrays", nodes},
        write_planes{"statistics write, 2 planes", plane_count},
        write_all{"statistics write, whole mesh", nodes};
    solver.step(state, dt);  // warm-up: first-touch and Poisson set-up stay out of the figures
    for (int s = 0; s < args.steps; ++s) {
      step.time([&] { solver.step(state, dt); });
      add_all.time([&] { all.add(state.time, state.velocity, state.pressure); });
      add_planes.time([&] { planes.add(state.time, state.velocity, state.pressure); });
      for (int k = 0; k < 10; ++k) sample.time([&] { probes.sample(state); });
    }
    io::FieldOutput output(mesh, metrics, local, args.out, "fields");
    flow::TensorField grad;
    flow::VectorField omega;
    fields.time([&] {
      flow::gradient(local, state.velocity, grad);
      flow::vorticity(grad, omega);
      output.write(state.time, {{"pressure", &state.pressure}},
                   {{"velocity", &state.velocity}, {"vorticity", &omega}});
    });
    io::CheckpointWriter writer(local, io::mesh_hash(mesh), args.out / "checkpoints");
    ckpt.time([&] { writer.write(state, 1, dt); });
    const double hwm0 = status_kb("VmHWM");
    ckpt_stats.time([&] {
      auto extras = all.checkpoint_arrays();
      for (auto& a : planes.checkpoint_arrays()) extras.push_back(std::move(a));
      writer.write(state, 2, dt, extras);
    });
    const double hwm1 = status_kb("VmHWM");
    write_planes.time([&] { planes.write(mesh, metrics, args.out / "statistics"); });
    write_all.time([&] { all.write(mesh, metrics, args.out / "statistics"); });

    const double stats_bytes = 1024 * local.comm.sum(rss1 - rss0);
    const double hwm_before = local.comm.max(hwm0), hwm_after = local.comm.max(hwm1);
    const double step_cpu = local.comm.max(step.total.cpu) / step.calls;
    const std::vector<const Cost*> costs{&step, &add_all,    &add_planes,   &sample,   &fields,
                                         &ckpt, &ckpt_stats, &write_planes, &write_all};
    std::string table;
    for (const Cost* c : costs) {
      const double cpu = local.comm.max(c->total.cpu) / c->calls;
      const double wall = local.comm.max(c->total.wall) / c->calls;
      const double ns = 1e9 * local.comm.sum(c->total.cpu) / c->calls / c->nodes;
      table +=
          fmt::format("  {:<34} {:>5} {:>10.3g} {:>10.3g} {:>9.3g} {:>9.3g} {:>10.4g}\n", c->what,
                      c->calls, cpu, local.comm.max(c->fastest), wall, 100 * cpu / step_cpu, ns);
    }
    if (rank == 0) {
      std::uintmax_t bytes = 0;
      for (const auto& f : std::filesystem::recursive_directory_iterator(args.out))
        if (f.is_regular_file()) bytes += f.file_size();
      fmt::print(
          "bench_output_cost: {}^3 periodic hexahedra, {:.0f} nodes, {} rank(s); {}\n  {} timed "
          "steps of dt {:.4g}; statistics {} bins; planes {:.0f} "
          "nodes; {} probes\n"
          "  {:<34} {:>5} {:>10} {:>10} {:>9} {:>9} {:>10}\n{}",
          args.n, nodes, size, bench::machine(), step.calls, dt, args.bins, plane_count,
          args.probes, "per call", "calls", "cpu s", "min cpu s", "wall s", "% step", "ns/node",
          table);
      fmt::print(
          "  (cpu s: mean over calls; % step: of the mean step; ns/node: CPU ns summed over ranks "
          "per covered node, per probe for the probes)\n"
          "  memory: whole-mesh statistics {:.1f} MB resident over all ranks = {:.1f} B per "
          "node and bin (documented 88)\n          = {:.1f} MB per phase bin for {:.0f} nodes; "
          "peak resident per rank {:.0f} MB before the checkpoint with statistics, {:.0f} MB "
          "after\n  files written: {:.1f} MB in {}{}\n",
          stats_bytes / 1e6, stats_bytes / nodes / args.bins, stats_bytes / args.bins / 1e6, nodes,
          hwm_before / 1024, hwm_after / 1024, bytes / 1e6, args.out.string(),
          args.keep ? "" : " (removed)");
      if (!args.keep) std::filesystem::remove_all(args.out);
    }
  });
}
