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
//     tetrahedra and about 15 k leaflet markers) under the full 100 mmHg: --steps coupled steps
//     (ProjectionRK4::step with the body-force hook + ImmersedStructure::finish_step), the CPU
//     time of the hook (4 calls per step: positions, solid forces, locate, spread, interpolate)
//     and, measured on the same markers in the same run, each of its parts per call; the shares
//     of the step follow. CPU time of this process (bench_util.hpp): the machine is shared, so
//     ratios within one run are the figures to trust, not absolute times.
//   bench_ibm_transfer_cost [--h 2.5e-4] [--depth-cells 48] [--steps 10] [--repeat 5]
//                           [--markers 1000,4000,16000] [--widths 3,4,6] [--cloud-h 5e-4]
// One rank is the intended use (the transfer's halo exchanges are included at more ranks).
#include <fmt/format.h>
#include <mpi.h>

#include <random>
#include <vector>

#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/ib_leakage/leakage_channel.hpp"

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
};

struct TransferCost {
  double locate = 0, spread = 0, interpolate = 0;  // CPU s per call
  double support = 0;                              // mean nodes per marker
};

// Times the three transfer operations on `markers` (repeat calls each).
TransferCost time_transfer(valsalva::flow::LocalMesh& local,
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
  v::LeakageChannel c(s, MPI_COMM_WORLD);
  if (root)
    fmt::print(
        "1. marker clouds in the leakage channel, h = {:g} m ({} fluid nodes); CPU us per marker "
        "per call\n  {:>7} {:>5} {:>8} {:>8} {:>8} {:>8} {:>12} {:>9}\n",
        s.h, c.local.global_nodes, "markers", "width", "locate", "spread", "interp", "stage",
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
      const auto t = time_transfer(c.local, o, markers, args.repeat);
      const double us = 1e6 / n, stage = (t.locate + t.spread + t.interpolate) * us;
      if (root)
        fmt::print("  {:>7.0f} {:>5g} {:>8.3f} {:>8.3f} {:>8.3f} {:>8.3f} {:>12.4f} {:>9.1f}\n", n,
                   w, t.locate * us, t.spread * us, t.interpolate * us, stage,
                   1e3 * stage / t.support, t.support);
    }
  }
}

void coupled_step(const Args& args, bool root) {
  const int steps = args.steps, repeat = args.repeat;
  v::LeakageSetup s;
  s.h = args.h;
  s.depth_cells = args.depth_cells;
  v::LeakageChannel c(s, MPI_COMM_WORLD);
  double t = cpu_seconds();
  const double dt = 0.5 * c.ib->stable_time_step();
  const double bound_seconds = cpu_seconds() - t;
  double hook = 0;
  auto inner = c.ib->body_force();
  c.flow->set_body_force([&](int k, double time, const valsalva::flow::VectorField& u,
                             valsalva::flow::VectorField& f) {
    const double t0 = cpu_seconds();
    inner(k, time, u, f);
    hook += cpu_seconds() - t0;
  });
  valsalva::flow::FlowState state{
      valsalva::flow::VectorField(c.local.num_local(), Eigen::Vector3d::Zero()),
      valsalva::flow::ScalarField(c.local.num_local(), 0.0), 0.0};
  for (int j : c.inlet_nodes) state.pressure[j] = s.pressure;
  double finish = 0;
  t = cpu_seconds();
  for (int n = 0; n < steps; ++n) {
    c.flow->step(state, dt);
    const double t0 = cpu_seconds();
    c.ib->finish_step(state);
    finish += cpu_seconds() - t0;
  }
  const double step = (cpu_seconds() - t) / steps;
  hook /= steps, finish /= steps;

  // The hook's parts on the same markers (wrapped into the periodic slab as the coupling does).
  const int m = c.ib->num_markers();
  Points markers(static_cast<std::size_t>(m));
  for (int a = 0; a < m; ++a) {
    markers[static_cast<std::size_t>(a)] = c.ib->positions().col(a);
    auto& z = markers[static_cast<std::size_t>(a)].z();
    z -= s.depth() * std::floor(z / s.depth());
  }
  const auto tc = time_transfer(c.local, c.ib->options().transfer, markers, repeat);
  Eigen::Matrix3Xd f(3, m);
  t = cpu_seconds();
  for (int k = 0; k < repeat; ++k) c.ib->body(0).forces(c.ib->positions(), f);
  const double forces = (cpu_seconds() - t) / repeat;
  const double transfer = tc.locate + tc.spread + tc.interpolate;
  if (root) {
    auto pct = [&](double x) { return 100 * x / step; };
    fmt::print(
        "2. coupled step: leakage channel h = {:g} m, {} fluid nodes, {} markers, kernel width "
        "{:g} h, dt {:.3e} s\n"
        "  step (flow + coupling) {:.4f} s CPU; body-force hook {:.4f} s/step = {:.1f} % "
        "(4 calls), finish_step {:.2e} s = {:.2f} %\n"
        "  per call: locate {:.4f} s ({:.2f} us/marker), spread {:.4f} s ({:.2f}), interpolate "
        "{:.4f} s ({:.2f}), solid forces {:.4f} s ({:.2f}); mean support {:.1f} nodes\n"
        "  shares of a step (x 4 stages): locate {:.1f} %, spread {:.1f} %, interpolate {:.1f} %, "
        "transfer total {:.1f} %, solid forces {:.1f} %; parts / measured hook = {:.3f}\n"
        "  stability bound (power iteration, once per run): {:.3f} s CPU = {:.1f} steps\n",
        s.h, c.local.global_nodes, m, s.kernel_width, dt, step, hook, pct(hook), finish,
        pct(finish), tc.locate, 1e6 * tc.locate / m, tc.spread, 1e6 * tc.spread / m, tc.interpolate,
        1e6 * tc.interpolate / m, forces, 1e6 * forces / m, tc.support, pct(4 * tc.locate),
        pct(4 * tc.spread), pct(4 * tc.interpolate), pct(4 * transfer), pct(4 * forces),
        4 * (transfer + forces) / hook, bound_seconds, bound_seconds / step);
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
  app.add_option("--steps", args.steps, "Coupled time steps timed")->check(bench::positive);
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
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    if (rank == 0) fmt::print("bench_ibm_transfer_cost: {} rank(s), {}\n", size, bench::machine());
    marker_clouds(args, rank == 0);
    coupled_step(args, rank == 0);
  });
}
