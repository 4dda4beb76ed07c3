// Study tool (not a test): one 2D Taylor-Green run (validation/taylor_green/tgv_run.hpp) with
// the discretisation choices open, printing the velocity and pressure errors and the truncation
// error of each term on the exact fields. Used to separate the space and time errors of the
// 4th-order operators (validation/taylor_green has the findings).
//   bench_taylor_green_study [--cell hexa|tetra] [--perturbation 0] [--n 32] [--scheme central4]
//                            [--order4 1] [--cfl 0.1] [--dt_max 0] [--tol 1e-10] [--re 100]
#include <fmt/format.h>
#include <mpi.h>

#include <string>

#include "validation/bench/bench_util.hpp"
#include "validation/taylor_green/tgv_run.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, status = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  try {
    const auto o = valsalva::bench::parse_options(
        argc, argv,
        {"cell", "perturbation", "n", "scheme", "order4", "cfl", "dt_max", "tol", "re"});
    const auto get = [&](const char* key, const char* def) {
      return o.count(key) ? o.at(key) : std::string(def);
    };
    valsalva::validation::TgvSpec spec;
    spec.cell_type = get("cell", "hexa");
    spec.perturbation = std::stod(get("perturbation", "0"));
    spec.n = std::stoi(get("n", "32"));
    spec.scheme = get("scheme", "central4");
    spec.fourth_order_operators = get("order4", "1") != "0";
    spec.cfl = std::stod(get("cfl", "0.1"));
    spec.dt_max = std::stod(get("dt_max", "0"));
    spec.poisson.tolerance = std::stod(get("tol", "1e-10"));
    spec.reynolds = std::stod(get("re", "100"));
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
  } catch (const std::exception& e) {
    if (rank == 0) fmt::print(stderr, "bench_taylor_green_study: {}\n", e.what());
    status = 1;
  }
  MPI_Finalize();
  return status;
}
