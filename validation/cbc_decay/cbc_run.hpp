// Decaying isotropic turbulence in the configuration of Comte-Bellot & Corrsin (J. Fluid Mech.
// 48, 273-337, 1971; grid M = 5.08 cm, U0 = 10 m/s): a periodic box of side L = 11 M, initialised
// at tU0/M = 42 with a divergence-free random field carrying the measured spectrum on the
// mesh's shells, advanced with the projection + RK4 solver (and a subgrid model) to the later
// measuring stations, where E(k) and the resolved energy are taken by FFT.
//
// Box: the box must hold the energy-containing scales as resolved modes. 2 pi / L must sit
// below the lowest measured wavenumber (0.15-0.20 cm^-1) and the box be many integral scales
// long; L = 11 M = 55.88 cm gives 2 pi / L = 0.1124 cm^-1 (the 42-spectrum peaks near
// 0.5 cm^-1, shell 4-5) and is the size used in LES studies of this experiment (about 2 pi in
// units of 11 M / 2 pi, e.g. Kang, Chester & Meneveau, J. Fluid Mech. 480, 2003).
// Resolved energy: the LES field carries shells s = 1 .. n/2 - 1 (k_s = s 2 pi / L, below the
// mesh cut-off pi / h); the measured spectrum holds all scales, so it is compared after the same
// sharp spectral filter: E_res = sum_{s=1}^{n/2-1} E(k_s) dk for both, the measured E taken at
// k_s by power-law interpolation (and extrapolation below the first measured wavenumber).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::validation {

inline constexpr double cbc_box_in_m = 11.0;         // L / M
inline constexpr double cbc_air_viscosity = 1.5e-5;  // m^2/s, air near 20 C
inline constexpr double cbc_air_density = 1.2;       // kg/m^3

struct CbcSpec {
  int n = 32;                       // nodes (cells) per side
  double box_in_m = cbc_box_in_m;   // L / M (other values: box-size studies)
  std::string model = "sigma";      // les::SubgridViscosity names; "none" = no model
  double constant = 0;              // 0 = the model's default
  std::string update = "step";      // les.update: nu_sgs per "step" or per RK "stage"
  std::string scheme = "central2";  // flow::make_convection_scheme
  double stability = 0.7;           // dt = stability / (RK4 Gershgorin rate), see run_diagnostics
  int start_station = 42;           // tU0/M of the initial spectrum (42, or 98 for studies)
  std::vector<int> stations = {98, 171};  // tU0/M after start_station
  // Rescaled spin-up before the start (les/spectrum_rescale.hpp), in large-eddy turnovers
  // L11 / u' of the initial spectrum (les::large_scales; 20.6 tU0/M at 42). See cbc_decay.cpp.
  double spinup_turnovers = 0.25;
  std::uint64_t seed = 1971;
  bool record_skewness = false;  // derivative skewness every step (one gather + 6 FFTs each)
  std::filesystem::path table;   // PHiLiP_cbc_experiment_table3.txt
};

struct CbcStation {
  int t_u0_over_m = 0;
  std::vector<double> k, E, E_exp;        // shells s = 1 .. n/2 - 1 [1/m], [m^3/s^2]
  double resolved = 0, resolved_exp = 0;  // sum E dk over those shells [m^2/s^2]
  double max_nu_sgs_over_nu = 0;
};

struct CbcResult {
  CbcStation initial;                          // tU0/M = 42 (after construction, before any step)
  std::vector<CbcStation> stations;            // spec.stations
  std::vector<double> time_u0_over_m, energy;  // every step: 1/2 <u.u> [m^2/s^2]
  std::vector<double> skewness;  // every step with spec.record_skewness: les::derivative_skewness
  std::vector<double> spinup_time_u0_over_m, spinup_skewness;  // before the rescaling
  int steps = 0, spinup_steps = 0;
  double spinup_u0_over_m = 0;  // the spin-up length in tU0/M
  double wall_seconds = 0;
  // Thread CPU time: steps (between the measurements after them, so with the run loop's own
  // per-step work), inside the subgrid model (run::Simulation::subgrid_cpu_seconds).
  double step_seconds = 0, sgs_seconds = 0;
  std::int64_t nodes = 0;
};

// Through the product's path: validation/cbc_decay/cbc_decay.toml with the spec as scene
// overrides, run by run::Simulation in a scratch folder (validation/scene_run.hpp).
CbcResult run_cbc(const CbcSpec& spec, MPI_Comm comm);

}  // namespace valsalva::validation
