// Study tool (not a test): one Comte-Bellot & Corrsin run (validation/cbc_decay/cbc_run.hpp)
// with every set-up choice open, printing the resolved energy against the filtered measurement
// at tU0/M = 42, 98, 171 and, with --spectra 1, E(k) per shell. Used to find where the 64^3
// sigma run misses the 171 station (the measured sensitivities are in cbc_decay.cpp's header).
//   bench_cbc_study [--n 64] [--model sigma] [--scheme central2] [--spinup 0.25]
//                   [--stability 0.7] [--update step] [--seed 1971] [--box 11] [--spectra 0]
//                   [--start 42]   (--help lists them)
#include <fmt/format.h>
#include <mpi.h>

#include <string>
#include <vector>

#include "validation/bench/cbc_options.hpp"
#include "validation/cbc_decay/cbc_run.hpp"

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  valsalva::validation::CbcSpec spec;
  spec.n = 64;
  bool spectra = false;
  bench::App app{"bench_cbc_study",
                 "One Comte-Bellot & Corrsin decaying-turbulence run with every set-up choice "
                 "open: resolved energy against the filtered measurement per station"};
  bench::add_cbc_options(app, spec);
  app.add_option("--spinup", spec.spinup_turnovers,
                 "Rescaled spin-up before the start, in large-eddy turnovers L11 / u'")
      ->check(bench::non_negative);
  app.add_option("--stability", spec.stability, "dt = stability / (RK4 Gershgorin rate)")
      ->check(bench::positive);
  app.add_option("--seed", spec.seed, "Seed of the random initial field");
  app.add_option("--box", spec.box_in_m, "Box side L / M")->check(bench::positive);
  app.add_option("--spectra", spectra, "Also print E(k) per shell at each station");
  app.add_option("--start", spec.start_station, "tU0/M of the initial spectrum")
      ->check(CLI::IsMember({42, 98}));
  return bench::mpi_main(app, argc, argv, [&](int rank, int) {
    std::erase_if(spec.stations, [&](int s) { return s <= spec.start_station; });
    spec.record_skewness = true;
    spec.table = std::string(VALSALVA_SOURCE_DIR) +
                 "/validation/refdata/cbc_decaying_turbulence/PHiLiP_cbc_experiment_table3.txt";
    const auto r = valsalva::validation::run_cbc(spec, MPI_COMM_WORLD);
    if (rank == 0) {
      fmt::print(
          "cbc_study: {}^3, box {} M, model {}, scheme {}, spin-up {} turnovers = {:.2f} tU0/M, "
          "stability {}, "
          "update {}, seed {}: {} steps, {:.1f} s\n",
          spec.n, spec.box_in_m, spec.model, spec.scheme, spec.spinup_turnovers, r.spinup_u0_over_m,
          spec.stability, spec.update, spec.seed, r.steps, r.wall_seconds);
      for (std::size_t i = 0; i < r.spinup_skewness.size(); ++i)
        fmt::print("  spin-up t {:.2f} tU0/M: derivative skewness {:.4f}\n",
                   r.spinup_time_u0_over_m[i], r.spinup_skewness[i]);
      for (std::size_t i = 0; i < r.skewness.size(); ++i)
        fmt::print("  tU0/M {:.2f}: energy {:.5e}, derivative skewness {:.4f}\n",
                   r.time_u0_over_m[i], r.energy[i], r.skewness[i]);
      auto stations = r.stations;
      stations.insert(stations.begin(), r.initial);
      for (const auto& s : stations) {
        fmt::print("  tU0/M {:>3}: resolved {:.5e} m2/s2, experiment {:.5e}, ratio {:.4f}\n",
                   s.t_u0_over_m, s.resolved, s.resolved_exp, s.resolved / s.resolved_exp);
        if (spectra)
          for (std::size_t i = 0; i < s.k.size(); ++i)
            fmt::print("    k {:.4f} 1/cm  E {:.4e}  E_exp {:.4e} cm3/s2  ratio {:.3f}\n",
                       s.k[i] / 100, s.E[i] * 1e6, s.E_exp[i] * 1e6, s.E[i] / s.E_exp[i]);
      }
    }
  });
}
