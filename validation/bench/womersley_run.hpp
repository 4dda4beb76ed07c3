// One Womersley pipe run with its own time loop, for bench_womersley_study's set-up choices and
// test_rank_agreement (the validation case validation/womersley runs its scenes through
// run::Simulation instead): a rigid straight pipe
// (Gmsh tetrahedra: 3D Delaunay, mesh/pipe_generator.hpp, or an extruded disk,
// mesh/extruded_pipe_generator.hpp) with a Womersley-profile sine inflow
// Q(t) = Q0 (1 + sin(2 pi t / T)), no-slip wall and an outlet, started from the exact solution
// (flow/womersley.hpp; velocity and the linear pressure of G(0)) so that the viscous transient
// of a start from rest, R^2 / (14.7 nu) = 3.1 s at Wo = 17, does not hide the discretisation
// error. Fluid and period of the reference experiment (rho 1100, mu 3.6e-3, T = 1 s); the radius
// gives the Womersley number exactly, R = Wo sqrt(nu T / (2 pi)), and the mean velocity is
// U0 = 5 D / T (3.48 L/min through D = 24.5 mm at Wo = 17), so every Wo takes the same number
// of steps per period at the same nodes per diameter.
// Sampled: at `phases` equally spaced times of the period `sample_period` (0-based), the nodes
// of the cross-section slab |z - L/2| <= h/2 against u_exact(r, t) e_z.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <string>
#include <vector>

#include "flow/boundary_conditions.hpp"
#include "flow/womersley.hpp"
#include "mesh/extruded_pipe_generator.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/pipe_generator.hpp"
#include "validation/gather_to_root.hpp"

namespace valsalva::validation {

struct WomersleySetup {
  double womersley = 17;
  double nodes_per_diameter = 20;  // mesh size D / nodes_per_diameter
  double length_in_diameters = 2;
  flow::BoundaryType outlet = flow::BoundaryType::pressure_outlet;
  std::string les_model = "none";  // none | sigma | wale | smagorinsky (default constants)
  double cfl = 0.4;                // dt ~ cfl h / u_peak, a whole number of steps per phase
  int phases = 8;
  int sample_period = 3;  // 3 = the 4th period
  double poisson_tolerance = 1e-10;
  int max_steps = 0;  // > 0: stop after that many steps (no sampling; rank tests)
  // Study knobs (bench_womersley_study): the solver options and the sampled region.
  bool stiffness_viscous = false;  // flow::ProjectionOptions::stiffness_viscous
  bool pressure_damping = true;    // flow::ProjectionOptions::pressure_damping
  bool sample_whole_pipe = false;  // sample every node, not only the mid-length slab
  bool unscaled_inlet = false;     // flow::BoundarySpec::unscaled_profile
  double mesh_size_factor = 1;     // Gmsh's size = factor * D / nodes_per_diameter
  mesh::PipeMeshOptions mesh;      // wall sizes are given in units of that Gmsh size
  // The mesh: false = Gmsh's 3D Delaunay tetrahedra (mesh/pipe_generator.hpp, `mesh`), true = a
  // Gmsh disk extruded into prism layers split into tetrahedra (mesh/extruded_pipe_generator.hpp).
  bool extruded = false;
  double layer_height = 1;        // extruded: the layers' height in units of the Gmsh size
  mesh::DiskWallGrading grading;  // extruded: sizes in units of the Gmsh size
};

struct PhaseSample {
  double time = 0;
  double max_error = 0;   // max |u_z - u_exact| / u_peak over the slab
  double l2_error = 0;    // volume-weighted RMS of u_z - u_exact over the slab / u_peak
  double transverse = 0;  // max |u_x, u_y| / u_peak over the slab
  // Mean flux over the middle third, sum V_j u_z / (sum V_j / pi R^2), of the run and of the
  // exact nodal values, and the imposed Q(t), m^3/s.
  double mean_flux = 0, exact_mean_flux = 0, flow_rate = 0;
  std::vector<double> x, y, z, r, u, exact, ux, uy;  // slab nodes (owned, gathered on rank 0)
};

struct WomersleyResult {
  flow::Womersley exact;  // the exact solution of the run
  double radius = 0, length = 0, h = 0, u_peak = 0, dt = 0, wall = 0;
  long nodes = 0;
  int steps = 0;
  std::vector<PhaseSample> phases;
  double max_error = 0, l2_error = 0, transverse = 0;  // worst over the phases
  // LES: nu_sgs / nu over owned nodes and all RK stages (max, and mean per node-stage).
  double max_nu_ratio = 0, mean_nu_ratio = 0;
  double first_stage_nu_ratio = 0;  // max at the first stage (the exact, parallel initial field)
  double interior_nu_ratio = 0;     // max over the middle third |z - L/2| <= L/6
  // Final velocity (3 per node) and pressure by dual node (global order, on every rank).
  std::vector<double> final_velocity, final_pressure;
  double max_divergence = 0;
};

// The pipe radius of a Womersley number (the fluid and period of the runs), m.
double womersley_radius(double womersley);

// The pipe mesh of a set-up, the same on every rank of `comm` (collective). Throws as the
// generators do.
mesh::Mesh womersley_mesh(const WomersleySetup& setup, MPI_Comm comm);

// Collective over `comm`.
WomersleyResult run_womersley(const WomersleySetup& setup, MPI_Comm comm);

// The fixed time step of a Womersley run: u_peak = max centreline velocity over the period
// (1000 samples), dt ~ cfl h / u_peak rounded down to a whole number of steps per phase.
struct PhaseSteps {
  double u_peak = 0, dt = 0;
  int per_phase = 0;
};
PhaseSteps phase_steps(const flow::Womersley& exact, double period, int phases, double cfl,
                       double h);

// Running max and sum of nu_sgs / nu over the owned nodes of every RK stage (an LES model on a
// laminar pipe flow).
struct NuSgsRecord {
  double max = 0, sum = 0, count = 0;
  void add(const mesh::LocalMesh& local, const flow::ScalarField& nu_sgs, double nu) {
    for (int i = 0; i < local.num_owned; ++i) {
      max = std::max(max, nu_sgs[i] / nu);
      sum += nu_sgs[i] / nu;
    }
    count += local.num_owned;
  }
  double global_max(const mesh::LocalMesh& local) const { return local.comm.max(max); }
  double global_mean(const mesh::LocalMesh& local) const {
    return local.comm.sum(sum) / std::max(1.0, local.comm.sum(count));
  }
};

}  // namespace valsalva::validation
