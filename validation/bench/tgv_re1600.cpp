// Benchmark (opt-in, not a test): the Taylor-Green vortex at Re = 1600, case C3.5 of the
// International Workshop on High-Order CFD Methods (box (2 pi)^3, V0 = L = 1, nu = 1/1600,
// u = sin x cos y cos z, v = -cos x sin y cos z, w = 0,
// p = (cos 2x + cos 2y)(cos 2z + 2)/16), run to t_end on an n^3 periodic hexahedral box with a
// fixed time step from the CFL number. Measures what the flow-solver issue asks for:
//   wall and CPU time, node-steps per second per core, the share of the Poisson solve, Poisson
//   iterations, peak resident memory per node, and the error of the dissipation rate -dE/dt
//   against the 512^3 spectral reference (validation/refdata/tgv_re1600/spectral_Re1600_512.gdiag):
//   max |eps - eps_ref| / max eps_ref over 0 <= t <= t_end, peak value and time.
// Writes OUT/tgv_<scheme>_<n>_np<ranks>.csv (t, E, -dE/dt) and appends one summary row to
// OUT/summary.csv; validation/bench/tgv_re1600_plot.py draws -dE/dt(t) and error vs CPU time.
// Usage: [mpiexec -n R] bench_tgv_re1600 [--n 32] [--scheme central2|central4] [--cfl 0.5]
//        [--t-end 10] [--operators order2|order4] [--out bench-results/tgv_re1600]
// --operators order4: the 4th-order gradient, divergence and viscous term
// (ProjectionOptions::fourth_order_operators); the CSV name and summary row carry "+op4".
// Measured numbers: validation/notes/bench_tgv_re1600.md.
#include <fmt/format.h>
#include <mpi.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/convection_scheme.hpp"
#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "io/box_generator.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/tgv_les/tgv_les_run.hpp"

using namespace valsalva;

namespace {

struct Args {
  int n = 32;
  std::string scheme = "central2";
  std::string operators = "order2";  // order4: ProjectionOptions::fourth_order_operators
  double cfl = 0.5, t_end = 10;
  std::filesystem::path out = "bench-results/tgv_re1600";
};

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::App app{"bench_tgv_re1600",
                 "Taylor-Green vortex at Re 1600 (workshop case C3.5): cost and the error of "
                 "-dE/dt against the 512^3 spectral reference"};
  app.add_option("--n", args.n, "Cells per side of the periodic box")->check(bench::positive);
  app.add_option("--scheme", args.scheme, "Convective scheme")
      ->check(CLI::IsMember(flow::convection_scheme_names()));
  app.add_option("--cfl", args.cfl, "Fixed dt from this CFL number")->check(bench::positive);
  app.add_option("--t-end", args.t_end, "End time")->check(bench::positive);
  app.add_option("--operators", args.operators,
                 "Gradient, divergence and viscous operators (order4: \"+op4\" in the names)")
      ->check(CLI::IsMember({"order2", "order4"}));
  app.add_option("--out", args.out, "Folder of the CSV files");
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    const bool order4 = args.operators == "order4";
    const std::string label = args.scheme + (order4 ? "+op4" : "");
    const double two_pi = 2 * std::numbers::pi, nu = 1.0 / 1600;
    io::BoxSpec spec;
    spec.cells = {args.n, args.n, args.n};
    spec.length = Eigen::Vector3d::Constant(two_pi);
    spec.periodic = {true, true, true};
    const auto mesh = io::generate_box(spec);
    const auto metrics = flow::compute_dual_metrics(mesh);
    flow::PartitionOptions partition;
    partition.ghost_layers = 2;
    const auto local = flow::distribute(mesh, metrics, MPI_COMM_WORLD, partition);

    flow::ProjectionOptions options;
    options.density = 1;
    options.viscosity = nu;
    options.scheme = args.scheme;
    options.fourth_order_operators = order4;
    options.poisson.tolerance = 1e-8;
    flow::ProjectionRK4 solver(local, options, flow::poisson_weights(mesh, metrics, local));

    auto state = validation::tgv_re1600_initial_state(local);
    auto energy = [&] { return validation::tgv_mean_energy(local, state.velocity); };
    const double h = two_pi / args.n;
    const int steps = static_cast<int>(std::ceil(args.t_end / (args.cfl * h)));
    const double dt = args.t_end / steps;

    std::vector<double> times{0}, energies{energy()};
    int max_its = 0;
    long total_its = 0;
    MPI_Barrier(MPI_COMM_WORLD);
    const double cpu0 = bench::cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) {
      const auto report = solver.step(state, dt);
      max_its = std::max(max_its, report.poisson.iterations);
      total_its += report.poisson.iterations;
      times.push_back(state.time);
      energies.push_back(energy());
      if (!std::isfinite(energies.back()))
        throw std::runtime_error(fmt::format("kinetic energy not finite at step {}", s + 1));
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = local.comm.sum(bench::cpu_seconds() - cpu0);  // all ranks

    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double peak_kb = local.comm.max(static_cast<double>(usage.ru_maxrss));
    const double owned = static_cast<double>(local.num_owned);
    const double bytes_per_node = local.comm.max(1024.0 * usage.ru_maxrss / owned);

    if (rank == 0) {
      const auto ref =
          validation::read_tgv_reference(std::filesystem::path(VALSALVA_SOURCE_DIR) /
                                         "validation/refdata/tgv_re1600/spectral_Re1600_512.gdiag");
      double ref_peak = 0, peak = 0, peak_t = 0, worst = 0;
      for (const auto& r : ref)
        if (r[0] <= args.t_end) ref_peak = std::max(ref_peak, r[2]);
      std::filesystem::create_directories(args.out);
      const auto csv = args.out / fmt::format("tgv_{}_{}_np{}.csv", label, args.n, size);
      std::ofstream out(csv);
      out << "t,E,dissipation,dissipation_reference\n";
      for (std::size_t i = 1; i + 1 < times.size(); ++i) {
        const double eps = -(energies[i + 1] - energies[i - 1]) / (times[i + 1] - times[i - 1]);
        const double eps_ref = validation::interpolate_tgv_reference(ref, times[i], 2);
        worst = std::max(worst, std::abs(eps - eps_ref));
        if (eps > peak) peak = eps, peak_t = times[i];
        out << fmt::format("{:.6f},{:.10e},{:.10e},{:.10e}\n", times[i], energies[i], eps, eps_ref);
      }
      const double node_steps = static_cast<double>(local.global_nodes) * steps;
      const auto summary = args.out / "summary.csv";
      const bool header = !std::filesystem::exists(summary);
      std::ofstream sum(summary, std::ios::app);
      if (header)
        sum << "scheme,n,ranks,steps,dt,wall_s,cpu_s,node_steps_per_s_per_core,"
               "poisson_its_mean,poisson_its_max,peak_rss_kb,bytes_per_node,"
               "dissipation_error_max_rel,peak,peak_time\n";
      sum << fmt::format(
          "{},{},{},{},{:.6g},{:.3f},{:.3f},{:.4g},{:.2f},{},{:.0f},{:.0f},{:.5f},{:.6f},{:.3f}\n",
          label, args.n, size, steps, dt, wall, cpu, node_steps / cpu, double(total_its) / steps,
          max_its, peak_kb, bytes_per_node, worst / ref_peak, peak, peak_t);
      fmt::print(
          "TGV Re 1600, {}^3 hexahedra, {}, {} ranks: {} steps of dt {:.4g} to t = {}\n"
          "  wall {:.1f} s, CPU {:.1f} s, {:.3g} node-steps/s/core, Poisson its mean {:.2f} max "
          "{}\n"
          "  peak RSS {:.0f} MB per rank, {:.0f} B per owned node\n"
          "  -dE/dt: max error {:.4f} of the reference peak {:.6f}; peak {:.6f} at t = {:.2f} "
          "(reference 0.012858 at 8.97)\n  -> {}\n",
          args.n, label, size, steps, dt, args.t_end, wall, cpu, node_steps / cpu,
          double(total_its) / steps, max_its, peak_kb / 1024, bytes_per_node, worst / ref_peak,
          ref_peak, peak, peak_t, csv.string());
    }
  });
}
