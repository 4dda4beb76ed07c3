// One Turek–Hron FSI run (Turek & Hron 2006; refdata/turek_hron_fsi), as users run it: the
// scene validation/turek_hron_fsi/turek_hron_fsi.toml with the run's overrides (mesh sizes, the
// bar's elements and tether, material, inflow and ramp, coupling, kernel, time), through
// run::Simulation and its one run loop (issue 20). The channel 2.5 x 0.41 with the rigid cylinder
// body-fitted in a tetrahedral slab (periodic in z), the elastic bar 0.35 x 0.02 immersed as Q2
// hexahedra glued to the cylinder's arc (St Venant–Kirchhoff, massless: rho_s = rho_f, the ITBM
// assumption), clamped at the cylinder by the tether. An observer samples the forces and point A.
//
// Plane strain: the bar spans the whole slab depth [0, Lz] and is z-periodic through the fluid:
// its faces z = 0 and z = Lz are wrapped onto the same fluid points, so the two images of a node
// get the same interpolated velocity (their separation stays Lz, F_zz = 1) and their equal and
// opposite z-forces (the plane-strain stress S_zz on the free faces) cancel in the spread force.
// No z-constraint is needed on interior nodes: in a z-invariant flow their z-velocity vanishes.
//
// Forces per unit depth on cylinder + bar (the benchmark's drag and lift): the body-fitted
// cylinder's consistent wall force (flow/wall_force.hpp, with the spread IB force density in the
// wall-node balance, since the clamped end's kernel reaches wall nodes and that share of the bar
// force goes straight into the cylinder) plus the force of the fluid on the bar. The bar's
// markers apply F_a to the fluid; by action and reaction the fluid applies -F_a to the bar, and
// sum_a F_a = tether reaction (internal forces sum to zero), so F_bar = -total_force. Drag = +x
// (downstream) and lift = +y components of F_cyl - sum_a F_a, divided by Lz.
#pragma once

#include <string>
#include <vector>

#include "validation/case.hpp"
#include "validation/turek_hron_fsi/turek_hron_data.hpp"

namespace valsalva::validation {

struct FsiLevel {
  double size_near = 0.01;  // m, triangles on the cylinder and in the box around the bar
  double size_far = 0.04;   // m, far field
  int layers = 5;           // prism layers of size_near in the slab depth: > the 4h kernel support
};

struct FsiSpec {
  TurekHronParameters p;
  FsiLevel level;
  double t_end = 10;  // s
  double ramp = 2;    // s, inflow (1 - cos(pi t / ramp)) / 2; 0: start from the developed profile
  double dt_fraction = 0.6;        // of the coupling bound (ibm/ib_stability.hpp): dt_safety
  double steady_window = 0;        // s; > 0: stop when drag and uy_A change by < steady_tolerance
  double steady_tolerance = 1e-3;  // relative, over one window
  double sample_interval = 1e-3;   // s between samples of the time series
  double initial_bend = 0;  // m: tip y-offset of a parabolic bend of the bar at t = 0 (a seed)
  int max_steps = 0;        // > 0: stop after this many steps (timing runs)
  bool profile = false;     // time spreading, interpolation and solid forces separately
  bool per_step = false;    // classic explicit IB coupling instead of per RK stage
  std::string kernel = "peskin4";  // immersed.kernel
  double kernel_width = 4;         // immersed.kernel_width, in h
};

struct FsiSample {
  double t, ux, uy, drag, lift, drag_bar, lift_bar;
};

struct FsiResult {
  std::vector<FsiSample> samples;
  long nodes = 0;
  int markers = 0, steps = 0, ranks = 1;
  double dt = 0, slab = 0, wall = 0;
  double loop_wall = 0;  // s in the time loop (wall minus mesh generation and set-up)
  double loop_cpu = 0;   // CPU s of this process in the time loop, max over ranks (shared machines)
  // |sum_j V_j f_j - sum_a F_a| / |sum_a F_a| at the end, f the density the observer spreads
  double balance_error = 0;
  double steady_change = 0;  // last relative change of drag over steady_window
  double max_w = 0;          // largest |z-velocity| of a marker (plane-strain check), m/s
  // Per call, seconds (profile only): locate, spread, interpolate, solid forces.
  double t_locate = 0, t_spread = 0, t_interp = 0, t_forces = 0;
};

// The scene overrides of `spec` (turek_hron_fsi.toml as is: FSI1 on the coarse mesh to 1.4 s).
std::vector<std::string> fsi_overrides(const FsiSpec& spec);

// Runs `spec` into ctx.out_dir / runs / `label` (the run's own log.csv and structures.csv).
FsiResult run_fsi(const Context& ctx, const FsiSpec& spec, const std::string& label);

}  // namespace valsalva::validation
