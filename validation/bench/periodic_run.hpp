// One streamwise-periodic Womersley pipe run with its own time loop, for bench_womersley_study's
// set-up choices (the validation case validation/womersley_periodic runs its scene through
// run::Simulation instead) (Womersley, J. Physiol. 127, 553-563, 1955, in its
// own form): a pipe periodic in z (mesh/periodic_pipe_generator.hpp: a triangulated disk extruded
// into identical layers, prisms or split tetrahedra), no-slip wall, driven by the oscillating
// body force rho G(t) e_z with the kinematic pressure gradient G(t) of the Womersley solution
// whose flow rate is Q(t) = Q0 (1 + sin(2 pi t / T)) (flow::Womersley::pressure_gradient).
// The exact velocity is the parallel field u(r, t) e_z and the pressure is uniform. Fluid, period
// and radius as in validation/womersley (rho 1100, mu 3.6e-3, T = 1 s, R = Wo sqrt(nu T / 2 pi),
// mean velocity 5 D / T). Started from the exact field. dt from the same convective CFL as the
// inlet-driven case, a whole number of steps per phase.
// Measured: axial error against the exact profile at `phases` times of the last period, the
// transverse velocity over the whole run (the departure from the parallel flow), and with an LES
// model nu_sgs / nu at every RK stage.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "flow/womersley.hpp"

namespace valsalva::validation {

struct PeriodicSetup {
  double womersley = 17;
  double nodes_per_diameter = 20;  // triangle size D / nodes_per_diameter
  int layers = 3;                  // identical layers of height h (the period is layers * h)
  bool split = false;              // tetrahedra from the split prisms instead of prisms
  std::string les_model = "none";  // none | sigma | wale | smagorinsky (default constants)
  double cfl = 0.4;
  int phases = 8;
  int periods = 4;
  // Studies: after every step, add the uniform axial velocity to the non-wall nodes that makes
  // the mean flux sum V_j u_z / length equal Q(t) (a flow-rate driven pipe, as the inlet-driven
  // one of validation/womersley, instead of the exact pressure gradient alone).
  bool flux_driven = false;
};

struct PeriodicResult {
  flow::Womersley exact;
  double radius = 0, h = 0, u_peak = 0, dt = 0, wall = 0;
  long nodes = 0;
  int steps = 0;
  double max_error = 0, l2_error = 0;          // worst over the phases of the last period, / u_peak
  double transverse = 0;                       // max |u_x, u_y| / u_peak over all steps and nodes
  double max_nu_ratio = 0, mean_nu_ratio = 0;  // LES: over owned nodes and all RK stages
  double max_divergence = 0;
  // Per sampled phase: the mean flux sum V_j u_z / length of the run and of the exact nodal
  // values, and Q(t) of the exact solution, m^3/s (studies: the flux error of the P1 field).
  std::vector<double> mean_flux, exact_mean_flux, flow_rate;
  // Last-period samples, gathered on rank 0: time, r, u_z, u_exact per owned node.
  std::vector<double> samples;
  // Final velocity (3 per node) by dual node (global order, on every rank).
  std::vector<double> final_velocity;
};

// Collective over `comm`.
PeriodicResult run_periodic_womersley(const PeriodicSetup& setup, MPI_Comm comm);

}  // namespace valsalva::validation
