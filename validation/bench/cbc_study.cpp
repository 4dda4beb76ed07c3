// Study tool (not a test): one Comte-Bellot & Corrsin run (validation/cbc_decay/cbc_run.hpp)
// with every set-up choice open, printing the resolved energy against the filtered measurement
// at tU0/M = 42, 98, 171 and, with --spectra 1, E(k) per shell. Used to find where the 64^3
// sigma run misses the 171 station (the measured sensitivities are in cbc_decay.cpp's header).
//   bench_cbc_study [--n 64] [--model sigma] [--scheme central2] [--spinup 0.25]
//                   [--stability 0.7] [--update step] [--seed 1971] [--box 11] [--spectra 0]
#include <fmt/format.h>
#include <mpi.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "validation/bench/bench_util.hpp"
#include "validation/cbc_decay/cbc_run.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, status = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  try {
    const auto o = valsalva::bench::parse_options(argc, argv,
                                                  {"n", "model", "scheme", "spinup", "stability",
                                                   "update", "seed", "box", "spectra", "start"});
    const auto get = [&](const char* key, const char* def) {
      return o.count(key) ? o.at(key) : std::string(def);
    };
    valsalva::validation::CbcSpec spec;
    spec.n = std::stoi(get("n", "64"));
    spec.model = get("model", "sigma");
    spec.scheme = get("scheme", "central2");
    spec.spinup_turnovers = std::stod(get("spinup", "0.25"));  // L11 / u' of the start
    spec.stability = std::stod(get("stability", "0.7"));
    spec.update = get("update", "step");
    spec.seed = std::stoull(get("seed", "1971"));
    spec.box_in_m = std::stod(get("box", "11"));
    spec.start_station = std::stoi(get("start", "42"));
    std::erase_if(spec.stations, [&](int s) { return s <= spec.start_station; });
    spec.record_skewness = true;
    const bool spectra = get("spectra", "0") != "0";
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
  } catch (const std::exception& e) {
    if (rank == 0) fmt::print(stderr, "bench_cbc_study: {}\n", e.what());
    status = 2;
  }
  MPI_Finalize();
  return status;
}
