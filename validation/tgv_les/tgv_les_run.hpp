// The Taylor-Green vortex at Re = 1600 (case C3.5 of the International Workshop on High-Order
// CFD Methods: box (2 pi)^3, V0 = L = 1, nu = 1/1600, u = sin x cos y cos z,
// v = -cos x sin y cos z, w = 0, p = (cos 2x + cos 2y)(cos 2z + 2)/16) on an n^3 periodic
// hexahedral box with a subgrid model, and its dissipation rate -dE/dt against the 512^3
// spectral reference (validation/refdata/tgv_re1600/spectral_Re1600_512.gdiag). Shared by the
// tgv_les validation case, its CTest versions and bench_tgv_re1600.
#pragma once

#include <mpi.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "flow/projection_rk4.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::validation {

// The initial velocity and pressure above at every local node.
flow::FlowState tgv_re1600_initial_state(const mesh::LocalMesh& local);
// Collective: mean kinetic energy sum V |u|^2 / 2 over owned nodes / (2 pi)^3.
double tgv_mean_energy(const mesh::LocalMesh& local, const flow::VectorField& u);

struct TgvLesSpec {
  std::string scheme = "central4";  // flow::make_convection_scheme
  std::string model = "sigma";      // les::SubgridViscosity names; "none" = no model
  double constant = 0;              // 0 = the model's default
  std::string update = "step";      // les.update: nu_sgs per "step" or per RK "stage"
  double cfl = 0.5;                 // dt = t_end / ceil(t_end / (cfl h / V0))
  double t_end = 10;
  bool fourth_order_operators = false;  // flow.fourth_order_operators
  std::vector<std::string> overrides;   // further "key=value" scene overrides, applied last
};

struct TgvLesResult {
  std::vector<double> time, energy;        // mean kinetic energy after every step (index 0: t = 0)
  std::vector<double> max_nu_sgs_over_nu;  // after every step (index 0: 0)
  int steps = 0;
  double dt = 0;
  double cpu_seconds = 0;   // of the time loop without these per-step records, summed over ranks
  double wall_seconds = 0;  // with set-up
  double loop_wall_seconds = 0;  // of the time loop (rank 0's; the per-step records included)
  // Max over the steps of dt (rc/2.83 + rv/2.79) with nu + max nu_sgs (flow/run_diagnostics.hpp,
  // derived for central2; central4's convective spectral radius is ~1.37x larger).
  double max_stability_number = 0;
  int poisson_iterations_max = 0;
  double poisson_iterations_mean = 0;  // per step
  // > 0: the run stopped at this time because the energy was no longer finite or exceeded its
  // initial value (it can only decay); time and energy end there.
  double blow_up_time = 0;
};

// validation/tgv_les/tgv_les.toml on the n^3 box with the spec as overrides, through
// run::Simulation into `run_dir` (empty: a scratch folder). Collective over `comm`.
TgvLesResult run_tgv_les(const TgvLesSpec& spec, int n, MPI_Comm comm,
                         const std::filesystem::path& run_dir = {});

// Rows (t, E, -dE/dt) of the spectral reference file (comment lines start with '#').
std::vector<std::array<double, 3>> read_tgv_reference(const std::filesystem::path& file);
// Linear interpolation of column `column` at time t.
double interpolate_tgv_reference(const std::vector<std::array<double, 3>>& ref, double t,
                                 int column);

// -dE/dt by central differences at the interior steps, compared with the reference.
struct TgvDissipation {
  std::vector<double> time, rate, reference;
  double peak = 0, peak_time = 0;                      // largest -dE/dt and its time
  double reference_peak = 0, reference_peak_time = 0;  // over the reference rows <= t_end
  double max_error = 0;                                // max |rate - reference| / reference_peak
};
TgvDissipation tgv_dissipation(const TgvLesResult& r, const std::vector<std::array<double, 3>>& ref,
                               double t_end);

}  // namespace valsalva::validation
