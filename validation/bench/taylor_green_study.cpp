// Study tool (not a test): one 2D Taylor-Green run (validation/taylor_green/tgv_run.hpp) with
// the discretisation choices open, printing the velocity and pressure errors and the truncation
// error of each term on the exact fields. Used to separate the space and time errors of the
// 4th-order operators (validation/taylor_green has the findings).
//   bench_taylor_green_study [--cell hexa|tetra] [--perturbation 0] [--n 32] [--scheme central4]
//                            [--order4 1] [--cfl 0.1] [--dt_max 0] [--tol 1e-10] [--re 100]
#include <fmt/format.h>
#include <mpi.h>

#include <string>

#include "flow/convection_scheme.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/taylor_green/tgv_run.hpp"

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  valsalva::validation::TgvSpec spec;
  spec.n = 32;
  spec.scheme = "central4";
  spec.fourth_order_operators = true;
  spec.cfl = 0.1;
  spec.poisson.tolerance = 1e-10;
  bench::App app{"bench_taylor_green_study",
                 "One 2D Taylor-Green run with the discretisation choices open: velocity and "
                 "pressure errors, and the truncation error of each term on the exact fields"};
  app.add_option("--cell", spec.cell_type, "Cell type of the box mesh")
      ->check(CLI::IsMember({"hexa", "tetra", "prism", "pyramid", "mixed"}));
  app.add_option("--perturbation", spec.perturbation, "Random node displacement, fraction of h")
      ->check(CLI::Range(0.0, 0.4));
  app.add_option("--n", spec.n, "Cells per side")->check(bench::positive);
  app.add_option("--scheme", spec.scheme, "Convective scheme")
      ->check(CLI::IsMember(valsalva::flow::convection_scheme_names()));
  app.add_option("--order4", spec.fourth_order_operators,
                 "4th-order gradient, divergence and viscous operators");
  app.add_option("--cfl", spec.cfl, "dt = t_end / ceil(t_end / (cfl h / U))")
      ->check(bench::positive);
  app.add_option("--dt_max", spec.dt_max, "> 0: dt is also at most this")
      ->check(bench::non_negative);
  app.add_option("--tol", spec.poisson.tolerance, "Poisson tolerance")->check(bench::positive);
  app.add_option("--re", spec.reynolds, "Reynolds number (inf: inviscid)")->check(bench::positive);
  return bench::mpi_main(app, argc, argv, [&](int rank, int) {
    const auto t = valsalva::validation::taylor_green_term_errors(spec, MPI_COMM_WORLD);
    const auto r = valsalva::validation::run_taylor_green(spec, MPI_COMM_WORLD);
    if (rank == 0)
      fmt::print(
          "{} pert {} n {} {} order4 {}: dt {:.4e} steps {} | velocity L2 {:.6e} Linf {:.6e} "
          "pressure L2 {:.6e} max div {:.3e} Poisson its {} wall {:.1f} s | truncation L2: "
          "convection {:.4e} viscous {:.4e} grad p {:.4e} div u {:.4e}\n",
          spec.cell_type, spec.perturbation, spec.n, spec.scheme, spec.fourth_order_operators, r.dt,
          r.steps, r.velocity_l2, r.velocity_linf, r.pressure_l2, r.max_divergence,
          r.max_poisson_iterations, r.wall_seconds, t.convection, t.viscous, t.pressure_gradient,
          t.divergence);
  });
}
