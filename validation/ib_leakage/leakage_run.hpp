// One run of the leakage channel (leakage_setup.hpp): ib_leakage.toml with the setup's
// overrides, run by run::Simulation like `valsalva run` (validation/scene_run.hpp); the pressure
// is ramped to the full load and held. Sampled by the run's observer, every t_end / 400 and at
// the end: the flow through the ends, the area the membrane displaces, the pressure jump between
// two region means (analysis::RegionMean: spheres of radius 1.5 mm on the centre line, 5 mm
// upstream of the membrane and 5 mm downstream of the static solution's most deflected point under
// the imposed load, beyond the widest kernel's reach of 3 mm), the tether reaction and the
// membrane's force on the fluid split between interior and wall nodes.
// The leak is measured by mass balance, not from the instantaneous flow: the fluid upstream of
// the membrane gains D dA/dt (A the area between the membrane's mid-surface and its flat start,
// per depth D), so what crosses the membrane is Q_leak = Q_in - dA/dt. Averaged over the window
// (the last half of the hold), the residual column oscillation cancels out of both terms:
// Q_leak = (int Q_in dt - [A]) / (t2 - t1). The other quantities are window means too.
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "validation/ib_leakage/leakage_setup.hpp"

namespace valsalva::validation {

struct LeakageSample {
  double time, inlet_pressure;  // s, Pa
  double flow_in, flow_out;     // through xmin (in) and xmax (out), per depth [m^2/s]
  double area;                  // displaced area per depth [m^2]
  double deflection;            // m
  double jump;                  // upstream - downstream region mean [Pa]
  double tether;                // -x tether reaction per depth [N/m]
  double interior, wall;        // -x membrane force on interior / wall nodes per depth [N/m]
  double max_marker_speed;      // m/s
};

struct LeakageResult {
  LeakageSetup setup;
  long long nodes = 0;
  int markers = 0;
  long long steps = 0;
  // Mean, smallest and largest time step of the run loop (a fraction of the coupling's bound,
  // re-evaluated as the membrane deforms, within the viscous limit: ib_leakage.toml).
  double dt = 0, dt_min = 0, dt_max = 0, wall_seconds = 0;
  std::vector<LeakageSample> history;
  // Window means (see above).
  double leak = 0;            // per depth [m^2/s]
  double leak_reference = 0;  // Bernoulli flow of the open channel, H sqrt(2 dp / rho) [m^2/s]
  double leak_change = 0;     // |leak(1st half of window) - leak(2nd half)| / leak_reference
  // Volume leaked through the moving membrane during the ramp / the area it displaced then.
  double ramp_leak = 0;
  double jump = 0;                            // Pa
  double tether = 0, interior = 0, wall = 0;  // N/m
  double interior_span = 0;      // height of the interior (not wall) nodes' dual volumes [m]
  double deflection = 0;         // m
  double static_deflection = 0;  // of the static membrane under the sustained jump [m]
  std::vector<double> profile_x, profile_p;  // pressure on the centre line (y = H/2) at the end
  Eigen::Matrix3Xd final_line, static_line;  // membrane centre line at the end, static
};

// Collective; the run goes to `run_dir` (log.csv, structures.csv, ...; empty: a scratch folder).
// Throws what the run loop throws when the run blows up.
LeakageResult run_leakage(const LeakageSetup& setup, const std::filesystem::path& run_dir,
                          MPI_Comm comm);

}  // namespace valsalva::validation
