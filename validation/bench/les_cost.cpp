// Benchmark (not a test): the share of a time step spent computing nu_sgs. Runs the
// Comte-Bellot & Corrsin case (validation/cbc_decay) on an n^3 hexahedral box to tU0/M = 98
// with a subgrid model and times, in the same run, the whole step (RK4 stages + Poisson) and
// the subgrid hook alone (velocity gradient -> nu_sgs at owned and ghost nodes). Target
// (issue 4): nu_sgs costs at most 10% of a step.
//   bench_les_cost [--n 48] [--model sigma] [--scheme central2] [--update step|stage]
#include <fmt/format.h>
#include <mpi.h>

#include <string>
#include <thread>

#include "validation/bench/cbc_options.hpp"
#include "validation/cbc_decay/cbc_run.hpp"

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  valsalva::validation::CbcSpec spec;
  spec.n = 48;
  bench::App app{"bench_les_cost",
                 "Share of a time step spent computing nu_sgs (CBC decaying turbulence to tU0/M "
                 "= 98; target <= 10 %)"};
  bench::add_cbc_options(app, spec);
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    spec.stations = {98};
    spec.table = std::string(VALSALVA_SOURCE_DIR) +
                 "/validation/refdata/cbc_decaying_turbulence/PHiLiP_cbc_experiment_table3.txt";
    const auto r = valsalva::validation::run_cbc(spec, MPI_COMM_WORLD);
    if (rank == 0) {
      const double ratio = r.sgs_seconds / r.step_seconds;
      fmt::print(
          "bench_les_cost: {}^3 hexa ({} nodes), model {}, scheme {}, update per {}, {} rank(s), "
          "{} hardware threads\n  {} steps: {:.3f} s CPU in steps ({:.4f} s/step), {:.3f} s in the "
          "subgrid hook (4 calls per step)\n  nu_sgs share of a step: {:.2f} % (target <= 10 %) -> "
          "{}\n",
          spec.n, r.nodes, spec.model, spec.scheme, spec.update, size,
          std::thread::hardware_concurrency(), r.steps, r.step_seconds, r.step_seconds / r.steps,
          r.sgs_seconds, 100 * ratio, ratio <= 0.10 ? "ok" : "ABOVE TARGET");
      // What the cost buys: resolved energy at 98 over the filtered experiment, to compare the
      // update policies (les.update) on the same case.
      const auto& s = r.stations.at(0);
      fmt::print("  E_res(98) / E_exp(98) = {:.5f} (no spin-up)\n", s.resolved / s.resolved_exp);
    }
  });
}
