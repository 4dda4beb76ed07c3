// One level of the case validation/womersley_periodic (womersley_periodic.toml, or
// womersley_periodic_flow_rate.toml for the flow-rate drive, with the level's overrides) run by
// run::Simulation and measured by the case's observer; shared with bench_womersley_study.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <string>
#include <vector>

#include "flow/womersley.hpp"

namespace valsalva::validation {

struct PeriodicLevel {
  double npd = 10;  // triangle size D / npd; the period is 3 layers of that size
  bool split = false;
  bool flow_rate = false;  // driven by its flow rate ([forcing] flow_rate) instead of G(t)
  std::string les = "none";
  int periods = 2;   // time.end in periods; sampled: the last
  double cfl = 0.4;  // convective CFL at the peak centreline velocity ...
  int phases = 8;    // ... rounded to a whole number of steps per phase (time.dt)
};

struct PeriodicRun {
  long nodes = 0;
  std::int64_t steps = 0;
  double dt = 0, u_peak = 0;
  // Over all nodes at the phases of the last period, / u_peak; transverse: max |u_x, u_y| /
  // u_peak over all steps; nu_sgs / nu of each step's last RK stage.
  double max_error = 0, l2_error = 0, transverse = 0;
  double max_nu_ratio = 0, mean_nu_ratio = 0, max_divergence = 0, wall = 0;
  std::vector<double> samples;         // rank 0: time, r, u_z, u_exact per node, last period
  std::vector<double> final_velocity;  // by dual node, every rank
  // Per sampled phase: its time and the mean flux sum V_j u_z / length of the run and of the
  // exact nodal values, m^3/s.
  std::vector<double> phase_time, mean_flux, exact_mean_flux;
};

// The Womersley solution of the case: R from Wo, Q0 = (5 D / T) pi R^2 (T = 1 s).
flow::Womersley periodic_womersley_exact(double womersley = 17);

// Runs a level into `run_dir` (empty: a scratch folder). Collective over `comm`.
PeriodicRun run_periodic_level(const PeriodicLevel& level, const flow::Womersley& exact,
                               const std::filesystem::path& run_dir, MPI_Comm comm);

}  // namespace valsalva::validation
