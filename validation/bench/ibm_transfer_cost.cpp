// Benchmark (not a test): the cost of the immersed-boundary transfer (ibm::DiracTransfer) per
// marker and call, and its share of a whole coupled time step.
//  1. Marker clouds (uniform random in the middle of the leakage channel, validation/ib_leakage)
//     of --markers counts, for each of --widths kernel widths (Peskin 4-point, RKPM-corrected):
//     CPU microseconds per marker for locate (nearest node, support search, moment matrix and
//     its correction), spread and interpolate, each repeated --repeat times, their sum (the
//     transfer work of one RK stage of the per_stage coupling), that sum per support node (ns),
//     and the mean support size (nodes per marker).
//  2. The leakage channel at --h and --depth-cells (default 0.25 mm, 48 cells: about 190 k fluid
//     nodes, 24 k membrane markers; the coarse valve mesh of the reference study has 0.47 M
//     tetrahedra and about 15 k leaflet markers) under the full 100 mmHg from the start (table
//     full_load.csv):
//     validation/ib_leakage/ib_leakage.toml with the channel's overrides (and --set ones), run
//     through run::Simulation like `valsalva run` for --steps steps (0: skipped). The CPU time
//     per step, the share of it the run spent locating markers (DiracTransfer::counts), and,
//     measured on the final markers after the run, each part of the coupling per call (locate,
//     spread, interpolate on a partition of the same mesh, solid forces); their shares of a step
//     follow as if every RK stage located its markers again (x 4, immersed.reuse_distance = 0;
//     the run itself keeps supports while markers stay near: see its measured locate share).
//     CPU time of this process (bench_util.hpp): the machine is shared, so ratios within one run
//     are the figures to trust, not absolute times.
//   bench_ibm_transfer_cost [--h 2.5e-4] [--depth-cells 48] [--steps 10] [--repeat 5]
//                           [--markers 1000,4000,16000] [--widths 3,4,6] [--cloud-h 5e-4]
//                           [--set KEY=VALUE ...]
// One rank is the intended use (the transfer's halo exchanges are included at more ranks).
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ibm/immersed_structure.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "scene/mesh_source.hpp"
#include "scene/scene.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/ib_leakage/leakage_setup.hpp"
#include "validation/scene_run.hpp"

namespace {

using valsalva::bench::cpu_seconds;
namespace v = valsalva::validation;
using Points = std::vector<Eigen::Vector3d>;

// The command line (defaults as in the header).
struct Args {
  double h = 2.5e-4, cloud_h = 5e-4;
  int depth_cells = 48, steps = 10, repeat = 5;
  std::vector<int> markers{1000, 4000, 16000};
  std::vector<double> widths{3, 4, 6};
  std::vector<std::string> settings;  // scene overrides of the coupled run
};

struct TransferCost {
  double locate = 0, spread = 0, interpolate = 0;  // CPU s per call
  double support = 0;                              // mean nodes per marker
};

// Times the three transfer operations on `markers` (repeat calls each).
TransferCost time_transfer(valsalva::mesh::LocalMesh& local,
                           const valsalva::ibm::TransferOptions& o, const Points& markers,
                           int repeat) {
  valsalva::ibm::DiracTransfer transfer(local, o);
  Points force(markers.size(), Eigen::Vector3d(1, 2, 3)), values(markers.size());
  valsalva::flow::VectorField field(local.num_local(), Eigen::Vector3d(0.1, 0.2, 0.3));
  TransferCost c;
  double t = cpu_seconds();
  for (int k = 0; k < repeat; ++k) transfer.locate(markers);
  c.locate = (cpu_seconds() - t) / repeat;
  t = cpu_seconds();
  for (int k = 0; k < repeat; ++k) transfer.spread(force, field);
  c.spread = (cpu_seconds() - t) / repeat;
  t = cpu_seconds();
  for (int k = 0; k < repeat; ++k) transfer.interpolate(field, values);
  c.interpolate = (cpu_seconds() - t) / repeat;
  c.support = static_cast<double>(transfer.weights().size()) / static_cast<double>(markers.size());
  return c;
}

void marker_clouds(const Args& args, bool root) {
  v::LeakageSetup s;
  s.h = args.cloud_h;
  // The channel's fluid mesh as the scene builds it, partitioned for the widest kernel.
  const auto leakage = valsalva::scene::load_scene(v::leakage_scene(), v::leakage_overrides(s));
  const auto mesh = valsalva::scene::build_mesh(leakage, MPI_COMM_WORLD);
  const auto metrics = valsalva::mesh::compute_dual_metrics(mesh);
  auto local = valsalva::mesh::distribute(
      mesh, metrics, MPI_COMM_WORLD,
      {v::leakage_ghost_layers(*std::max_element(args.widths.begin(), args.widths.end())),
       valsalva::mesh::PartitionMethod::metis});
  if (root)
    fmt::print(
        "1. marker clouds in the leakage channel, h = {:g} m ({} fluid nodes); CPU us per marker "
        "per call\n  {:>7} {:>5} {:>8} {:>8} {:>8} {:>8} {:>12} {:>9}\n",
        s.h, local.global_nodes, "markers", "width", "locate", "spread", "interp", "stage",
        "ns/sup.node", "support");
  std::mt19937_64 rng(7);
  for (const double n : args.markers) {
    Points markers(static_cast<std::size_t>(n));
    std::uniform_real_distribution<double> x(s.upstream - 4e-3, s.upstream + 4e-3), y(0, s.height),
        z(0, s.depth());
    for (auto& p : markers) p = {x(rng), y(rng), z(rng)};
    for (const double w : args.widths) {
      valsalva::ibm::TransferOptions o;
      o.kernel = {valsalva::ibm::KernelType::peskin4, w};
      const auto t = time_transfer(local, o, markers, args.repeat);
      const double us = 1e6 / n, stage = (t.locate + t.spread + t.interpolate) * us;
      if (root)
        fmt::print("  {:>7.0f} {:>5g} {:>8.3f} {:>8.3f} {:>8.3f} {:>8.3f} {:>12.4f} {:>9.1f}\n", n,
                   w, t.locate * us, t.spread * us, t.interpolate * us, stage,
                   1e3 * stage / t.support, t.support);
    }
  }
}

void coupled_step(const Args& args, bool root) {
  if (args.steps == 0) return;
  const int steps = args.steps, repeat = args.repeat;
  v::LeakageSetup s;
  s.h = args.h;
  s.depth_cells = args.depth_cells;
  // The full load from the start: the held table full_load.csv instead of the case's ramp.
  auto overrides = v::leakage_overrides(s);
  overrides.insert(overrides.end(), {"boundary.xmin.pressure_file=full_load.csv",
                                     fmt::format("time.max_steps={}", steps)});
  overrides.insert(overrides.end(), args.settings.begin(), args.settings.end());
  double start = 0, step = 0, located = 0, dt = 0, forces = 0;
  long long nodes = 0;
  int m = 0;
  TransferCost tc;
  v::SceneRun measure;
  measure.at_start = [&](const valsalva::run::Simulation&) { start = cpu_seconds(); };
  measure.at_end = [&](const valsalva::run::Simulation& sim) {
    const auto& comm = sim.local().comm;
    step = comm.max(cpu_seconds() - start) / steps;
    const auto& ib = *sim.immersed();
    located = comm.max(ib.transfer().counts().cpu_seconds) / steps;
    dt = sim.state().time / steps;
    nodes = sim.local().global_nodes;
    // The coupling's parts on the final markers (wrapped into the periodic slab as the coupling
    // does), on a partition of the run's mesh of its own (the run's is read-only here).
    m = ib.num_markers();
    Points markers(static_cast<std::size_t>(m));
    for (int a = 0; a < m; ++a) {
      markers[static_cast<std::size_t>(a)] = ib.positions().col(a);
      auto& z = markers[static_cast<std::size_t>(a)].z();
      z -= s.depth() * std::floor(z / s.depth());
    }
    auto local = valsalva::mesh::distribute(
        sim.mesh(), sim.metrics(), comm.get(),
        {v::leakage_ghost_layers(s.kernel_width), valsalva::mesh::PartitionMethod::metis});
    tc = time_transfer(local, ib.options().transfer, markers, repeat);
    Eigen::Matrix3Xd f(3, m);
    const double t = cpu_seconds();
    for (int k = 0; k < repeat; ++k) ib.body(0).forces(ib.positions(), f);
    forces = (cpu_seconds() - t) / repeat;
  };
  v::run_scene_file(v::leakage_scene(), overrides, "", MPI_COMM_WORLD, measure);
  const double transfer = tc.locate + tc.spread + tc.interpolate;
  if (root) {
    auto pct = [&](double x) { return 100 * x / step; };
    fmt::print(
        "2. coupled step: leakage channel h = {:g} m, {} fluid nodes, {} markers, kernel width "
        "{:g} h, mean dt {:.3e} s\n"
        "  step (the run loop: flow + coupling + logs) {:.4f} s CPU; locating markers in the run "
        "{:.4f} s/step = {:.1f} %\n"
        "  per call: locate {:.4f} s ({:.2f} us/marker), spread {:.4f} s ({:.2f}), interpolate "
        "{:.4f} s ({:.2f}), solid forces {:.4f} s ({:.2f}); mean support {:.1f} nodes\n"
        "  shares of the step were every RK stage to locate again (reuse_distance = 0, x 4): "
        "locate {:.1f} %, spread {:.1f} %, interpolate {:.1f} %, "
        "transfer total {:.1f} %, solid forces {:.1f} %\n",
        s.h, nodes, m, s.kernel_width, dt, step, located, pct(located), tc.locate,
        1e6 * tc.locate / m, tc.spread, 1e6 * tc.spread / m, tc.interpolate,
        1e6 * tc.interpolate / m, forces, 1e6 * forces / m, tc.support, pct(4 * tc.locate),
        pct(4 * tc.spread), pct(4 * tc.interpolate), pct(4 * transfer), pct(4 * forces));
  }
}

}  // namespace

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  Args args;
  bench::App app{"bench_ibm_transfer_cost",
                 "Cost of the immersed-boundary transfer per marker and call, and its share of "
                 "a coupled time step of the leakage channel"};
  app.add_option("--h", args.h, "Fluid mesh size of the coupled leakage channel [m]")
      ->check(bench::positive);
  app.add_option("--depth-cells", args.depth_cells, "Cells across the channel's periodic depth")
      ->check(bench::positive);
  app.add_option("--steps", args.steps, "Coupled time steps timed (0: no coupled run)")
      ->check(bench::non_negative);
  app.add_option("--repeat", args.repeat, "Repetitions of each timed transfer call")
      ->check(bench::positive);
  app.add_option("--markers", args.markers, "Marker counts of the clouds (comma-separated)")
      ->delimiter(',')
      ->check(bench::positive);
  app.add_option("--widths", args.widths, "Kernel widths in h (comma-separated)")
      ->delimiter(',')
      ->check(bench::positive);
  app.add_option("--cloud-h", args.cloud_h, "Fluid mesh size of the marker-cloud channel [m]")
      ->check(bench::positive);
  app.add_option("--set", args.settings,
                 "Scene override KEY=VALUE of the coupled run (repeatable), e.g. "
                 "immersed.reuse_distance=0");
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    if (rank == 0) fmt::print("bench_ibm_transfer_cost: {} rank(s), {}\n", size, bench::machine());
    marker_clouds(args, rank == 0);
    coupled_step(args, rank == 0);
  });
}
