// Benchmark (opt-in, not a test): time per explicit internal-force evaluation of the fine
// leaflet mesh size (1536 Q2 hexahedra, quasi-incompressible neo-Hookean), for the full 3x3x3
// and the 3x3x2 Gauss rules, and (with --static) the static solve time of the leaflet-closure case
// on its fine 512-element mesh (one leaflet of the 1536-element valve).
// CPU time of this thread is the metric (the machine may be shared); wall time is printed too.
// Usage: bench_structure_forces [--repetitions 200] [--static]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <string>

#include "structure/mesh_generators.hpp"
#include "structure/solid_forces.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/leaflet_closure/leaflet_closure.hpp"

using namespace valsalva::structure;

int main(int argc, char** argv) {
  int reps = 200;
  bool static_solve = false;
  valsalva::bench::App app{"bench_structure_forces",
                           "Time per explicit internal-force evaluation of the fine leaflet mesh "
                           "(3x3x3 and 3x3x2 Gauss rules) and, with --static, the leaflet-closure "
                           "static solve"};
  app.add_option("--repetitions", reps, "Timed evaluations per Gauss rule")
      ->check(valsalva::bench::positive);
  app.add_flag("--static", static_solve, "Also time the leaflet-closure static solve (512 Q2)");
  if (const auto code = valsalva::bench::parse(app, argc, argv)) return *code;
  ShellPatch p;  // leaflet: R 12.5 mm, 120 degrees, t 0.15 mm
  p.n_angle = 48;
  p.n_height = 32;
  p.n_thickness = 1;
  const SolidMesh mesh = cylindrical_shell_patch(HexOrder::q2, p);
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  fmt::print("mesh: {} Q2 hexahedra, {} nodes\n", mesh.num_elements(), mesh.num_nodes());
  for (std::array<int, 3> rule : {std::array<int, 3>{3, 3, 3}, std::array<int, 3>{3, 3, 2}}) {
    SolidForces forces(mesh, *mat, rule);
    Eigen::Matrix3Xd x = mesh.X, f(3, mesh.num_nodes());
    for (int n = 0; n < mesh.num_nodes(); ++n) x(2, n) += 1e-4 * std::sin(300 * mesh.X(0, n));
    // CPU time of this thread (the machine may be shared, so wall time overstates the cost).
    auto time = [&](int n, auto&& eval) {
      eval();  // warm-up
      timespec c0, c1;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
      const auto t0 = std::chrono::steady_clock::now();
      double min_det = 1e300;
      for (int r = 0; r < n; ++r) min_det = std::min(min_det, eval());
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / n;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
      if (!(min_det > 0)) fmt::print("warning: det F = {} <= 0\n", min_det);
      return std::pair{((c1.tv_sec - c0.tv_sec) + 1e-9 * (c1.tv_nsec - c0.tv_nsec)) / n, wall};
    };
    const auto [s, wall] = time(reps, [&] { return forces.internal_forces(x, f); });
    const auto [sd, walld] =
        time(std::max(1, reps / 5), [&] { return forces.internal_forces_direct(x, f); });
    fmt::print(
        "gauss {}x{}x{}: {:.3f} ms CPU per evaluation ({:.3f} ms wall), {:.1f} ns per element, "
        "{:.1f} ns per Gauss point; {:.2f} x the 2 ms target ({}) [{}]\n",
        rule[0], rule[1], rule[2], 1e3 * s, 1e3 * wall, 1e9 * s / mesh.num_elements(),
        1e9 * s / (mesh.num_elements() * forces.gauss_points_per_element()), s / 2e-3,
        s <= 2e-3 ? "met" : "MISSED", forces.sum_factorised() ? "sum-factorised" : "direct");
    fmt::print("  direct Gauss-point loop (reference): {:.3f} ms CPU ({:.3f} ms wall), {:.1f}x\n",
               1e3 * sd, 1e3 * walld, sd / s);
  }
  if (static_solve) {
    timespec c0, c1;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
    const auto lc = valsalva::validation::close_leaflet(true, 300.0, false);
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
    fmt::print(
        "leaflet closure static solve, {} Q2 elements, 300 Pa: {} after {} Newton iterations ({} "
        "cuts), "
        "{:.1f} s wall, {:.1f} s CPU [{}]\n",
        lc.mesh.num_elements(), lc.result.converged ? "converged" : "FAILED", lc.result.iterations,
        lc.result.cuts, lc.seconds, (c1.tv_sec - c0.tv_sec) + 1e-9 * (c1.tv_nsec - c0.tv_nsec),
        lc.result.solver);
  }
  return 0;
}
