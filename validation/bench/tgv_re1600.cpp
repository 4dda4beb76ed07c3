// Benchmark (opt-in, not a test): the Taylor-Green vortex at Re = 1600, case C3.5 of the
// International Workshop on High-Order CFD Methods (box (2 pi)^3, V0 = L = 1, nu = 1/1600,
// u = sin x cos y cos z, v = -cos x sin y cos z, w = 0,
// p = (cos 2x + cos 2y)(cos 2z + 2)/16), run to t_end on an n^3 periodic hexahedral box with a
// fixed time step from the CFL number: validation/tgv_les/tgv_les.toml (no model unless --model),
// through run::Simulation and its run loop (validation/tgv_les/tgv_les_run.hpp), as `valsalva run`
// runs it. Measures what the flow-solver issue asks for:
//   wall time (with set-up) and CPU time (of the time loop, all ranks), node-steps per second
//   per core, Poisson
//   iterations, peak resident memory per node, and the error of the dissipation rate -dE/dt
//   against the 512^3 spectral reference (validation/refdata/tgv_re1600/spectral_Re1600_512.gdiag):
//   max |eps - eps_ref| / max eps_ref over 0 <= t <= t_end, peak value and time.
// Writes OUT/tgv_<scheme>_<n>_np<ranks>.csv (t, E, -dE/dt) and appends one summary row to
// OUT/summary.csv; validation/bench/tgv_re1600_plot.py draws -dE/dt(t) and error vs CPU time.
// Usage: [mpiexec -n R] bench_tgv_re1600 [--n 32] [--scheme central2|central4] [--cfl 0.5]
//        [--t-end 10] [--operators order2|order4] [--model none|sigma|wale|smagorinsky]
//        [--out bench-results/tgv_re1600] [--set key=value ...] [--triad]
// --set: further scene overrides (e.g. poisson.strong_threshold=0.25), as `valsalva run --set`.
// --triad: also measure the STREAM-like triad bandwidth of one core (stream_triad.hpp) and print
// it beside the node-steps per second, for the memory-bandwidth bound of the edge loops.
// --operators order4: the 4th-order gradient, divergence and viscous term
// (ProjectionOptions::fourth_order_operators); the CSV name and summary row carry "+op4".
// Measured numbers: validation/notes/bench_tgv_re1600.md.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mpi.h>
#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/comm.hpp"
#include "flow/convection_scheme.hpp"
#include "les/sgs_model.hpp"
#include "run/data_dir.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/bench/bench_util.hpp"
#include "validation/bench/stream_triad.hpp"
#include "validation/tgv_les/tgv_les_run.hpp"

using namespace valsalva;

namespace {

struct Args {
  int n = 32;
  std::string scheme = "central2";
  std::string operators = "order2";  // order4: ProjectionOptions::fourth_order_operators
  std::string model = "none";        // les.model
  double cfl = 0.5, t_end = 10;
  std::filesystem::path out = "bench-results/tgv_re1600";
  std::vector<std::string> overrides;  // --set
  bool triad = false;
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
  app.add_option("--model", args.model,
                 "Subgrid model (les.model; not \"none\": \"+MODEL\" in the names)")
      ->check(CLI::IsMember(les::sgs_kind_names()));
  app.add_option("--out", args.out, "Folder of the CSV files");
  app.add_option("--set", args.overrides, "Further scene override key=value (repeatable)");
  app.add_flag("--triad", args.triad, "Also measure the STREAM-like triad bandwidth");
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    const bool order4 = args.operators == "order4";
    const std::string label =
        args.scheme + (order4 ? "+op4" : "") + (args.model != "none" ? "+" + args.model : "");
    // The scene of validation/tgv_les, through run::Simulation (issue 20).
    validation::TgvLesSpec spec;
    spec.scheme = args.scheme;
    spec.model = args.model;
    spec.cfl = args.cfl;
    spec.t_end = args.t_end;
    spec.fourth_order_operators = order4;
    spec.overrides = args.overrides;
    const auto r = validation::run_tgv_les(spec, args.n, MPI_COMM_WORLD);
    if (r.blow_up_time > 0)
      throw std::runtime_error(fmt::format(
          "kinetic energy above its initial value or not finite at t = {}", r.blow_up_time));

    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const core::Comm comm(MPI_COMM_WORLD);
    const double peak_kb = comm.max(static_cast<double>(usage.ru_maxrss));
    const double nodes = std::pow(double(args.n), 3);  // the periodic box's dual nodes
    const double bytes_per_node = comm.max(1024.0 * usage.ru_maxrss / (nodes / size));

    if (rank == 0) {
      const auto ref = validation::read_tgv_reference(
          run::data_dir() / "validation/refdata/tgv_re1600/spectral_Re1600_512.gdiag");
      const auto d = validation::tgv_dissipation(r, ref, args.t_end);
      std::filesystem::create_directories(args.out);
      const auto csv = args.out / fmt::format("tgv_{}_{}_np{}.csv", label, args.n, size);
      std::ofstream out(csv);
      out << "t,E,dissipation,dissipation_reference\n";
      for (std::size_t i = 0; i < d.time.size(); ++i)
        out << fmt::format("{:.6f},{:.10e},{:.10e},{:.10e}\n", d.time[i], r.energy[i + 1],
                           d.rate[i], d.reference[i]);
      const double node_steps = nodes * r.steps;
      const auto summary = args.out / "summary.csv";
      const bool header = !std::filesystem::exists(summary);
      std::ofstream sum(summary, std::ios::app);
      if (header)
        sum << "scheme,n,ranks,steps,dt,wall_s,loop_wall_s,cpu_s,node_steps_per_s_per_core,"
               "poisson_its_mean,poisson_its_max,peak_rss_kb,bytes_per_node,"
               "dissipation_error_max_rel,peak,peak_time\n";
      sum << fmt::format(
          "{},{},{},{},{:.6g},{:.3f},{:.3f},{:.3f},{:.4g},{:.2f},{},{:.0f},{:.0f},"
          "{:.5f},{:.6f},{:.3f}\n",
          label, args.n, size, r.steps, r.dt, r.wall_seconds, r.loop_wall_seconds, r.cpu_seconds,
          node_steps / r.cpu_seconds, r.poisson_iterations_mean, r.poisson_iterations_max, peak_kb,
          bytes_per_node, d.max_error, d.peak, d.peak_time);
      fmt::print(
          "TGV Re 1600, {}^3 hexahedra, {}, {} ranks: {} steps of dt {:.4g} to t = {}\n"
          "  wall {:.1f} s (with set-up), {:.1f} s (time loop), CPU {:.1f} s (time loop), {:.3g} "
          "node-steps/s/core, "
          "Poisson its mean {:.2f} max {}\n"
          "  peak RSS {:.0f} MB per rank, {:.0f} B per owned node\n"
          "  -dE/dt: max error {:.4f} of the reference peak {:.6f}; peak {:.6f} at t = {:.2f} "
          "(reference 0.012858 at 8.97)\n  -> {}\n",
          args.n, label, size, r.steps, r.dt, args.t_end, r.wall_seconds, r.loop_wall_seconds,
          r.cpu_seconds, node_steps / r.cpu_seconds, r.poisson_iterations_mean,
          r.poisson_iterations_max, peak_kb / 1024, bytes_per_node, d.max_error, d.reference_peak,
          d.peak, d.peak_time, csv.string());
      fmt::print("  {}\n", bench::machine());
      if (!args.overrides.empty()) fmt::print("  overrides: {}\n", fmt::join(args.overrides, " "));
      fmt::print("  final mean kinetic energy {:.17e}\n", r.energy.back());
    }
    if (args.triad) {
      // After the run, one rank at a time would understate a shared bus: every rank measures.
      const auto triad = bench::stream_triad();
      const double per_core = comm.sum(triad.bytes_per_second) / size;
      if (rank == 0)
        fmt::print("  STREAM-like triad: {:.2f} GB/s per core ({} ranks at once; checksum {:g})\n",
                   per_core / 1e9, size, triad.checksum);
    }
  });
}
