// Scene keys of the flow solver (flow/projection_rk4, flow/pressure_poisson, run/run_loop):
// fluid properties, time stepping, the pressure Poisson solver, the initial state and the
// field output; and their reader flow_run_options.
#include "scene/scene_keys_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flow/convection_scheme.hpp"
#include "flow/initial_condition.hpp"
#include "flow/time_scheme.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_keys_rheology.hpp"

namespace valsalva::scene {

namespace {
constexpr double max_field_outputs = 1e5;  // fields written per run (output.interval in s)
constexpr double max_time_steps = 1e9;     // steps a run may take to time.end
constexpr double default_density = 1100.0, default_viscosity = 3.6e-3;  // the reference fluid

// The one rule for runs that would not end in a lifetime: a time step `dt` that takes more than
// max_time_steps steps to time.end, unless time.max_steps caps the run. The implied step count
// when refused, 0 when accepted.
double refused_step_count(const scene::TimeOptions& t, double dt) {
  if (t.max_steps > 0 || !(dt > 0)) return 0;
  const double steps = t.end / dt;
  return steps > max_time_steps ? steps : 0;
}
}  // namespace

void declare_flow_keys(Schema& s) {
  s.section("flow", "Fluid properties and the discretisation of the momentum equation.");
  s.real("flow.density")
      .def(default_density)
      .above(0)
      .unit_of("kg/m3")
      .doc(
          "Fluid density; 1100 is the blood-analogue fluid of the reference pulse-duplicator "
          "experiment. With time.dt = 0, a density so small (nu = viscosity / density so large) "
          "that the viscous bound dt <= time.fourier h^2 / nu (h the mesh's smallest cube root "
          "of a dual volume) takes more than 1e9 steps to time.end is refused unless "
          "time.max_steps is set");
  s.real("flow.viscosity")
      .def(default_viscosity)
      .at_least(0)
      .unit_of("Pa s")
      .doc(
          "Dynamic viscosity (Newtonian); 3.6e-3 is the reference experiment's blood analogue; "
          "the 1e9-step rule of flow.density applies; not used by the momentum equation with a "
          "non-Newtonian flow.viscosity_model");
  s.choice("flow.scheme", flow::convection_scheme_names())
      .def("central2")
      .unit_of("-")
      .doc(
          "Convective scheme: central2 = 2nd-order centred, kinetic-energy conserving; central4 = "
          "4th-order centred edge scheme (Hermite face values, 4th order on uniform hexahedra and "
          "split tetrahedra, lower on irregular meshes; needs partition.ghost_layers >= 2)");
  s.boolean("flow.fourth_order_operators")
      .def(false)
      .unit_of("-")
      .doc(
          "4th-order laminar viscous term, pressure gradient and divergence (Hermite-corrected "
          "edge operators, flow/operators_order4.hpp): with flow.scheme = central4 the velocity "
          "converges at 4th order on uniform hexahedra and split tetrahedra (Taylor-Green case); "
          "the Poisson matrix, the pressure damping at boundaries and an LES model's subgrid "
          "term stay 2nd order; refused with a non-Newtonian fluid; needs "
          "partition.ghost_layers >= 2");
  s.choice("flow.viscous_weights", {"two_point", "stiffness"})
      .def("two_point")
      .unit_of("-")
      .doc(
          "Edge weights of the 2nd-order laminar viscous term: two_point = two-point weights "
          "with the non-orthogonal correction from nodal gradients; stiffness = the Poisson "
          "matrix's P1 stiffness weights without correction (on tetrahedra the median-dual flux "
          "of the piecewise-linear velocity; the DFG cylinder benchmark uses it)");
  s.real("flow.velocity_limit")
      .def(50.0)
      .above(0)
      .unit_of("m/s")
      .doc(
          "A velocity magnitude above this stops the run with a diagnosis (blood flows stay below "
          "a few m/s)");

  s.section("time", "Time stepping of the projection + RK4 scheme.");
  s.real("time.end")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc("End time; 0 takes no time step (only the initial state is written)");
  s.real("time.dt").def(0.0).at_least(0).unit_of("s").doc(
      "Fixed time step, refused beyond the RK4 stability limit and when it takes more than 1e9 "
      "steps to time.end without time.max_steps; 0 = from time.cfl and time.fourier at every "
      "step");
  s.real("time.cfl")
      .def(0.5)
      .above(0)
      .unit_of("-")
      .doc("Target convective CFL number max |u| dt / h when time.dt = 0");
  s.real("time.fourier")
      .def(0.2)
      .above(0)
      .unit_of("-")
      .doc(
          "Target viscous Fourier number max nu dt / h^2 when time.dt = 0 (nu = viscosity / "
          "density)");
  s.real("time.stability_fraction")
      .def(0.0)
      .in_range(0, 1)
      .unit_of("-")
      .doc(
          "> 0 with time.dt = 0: dt = this fraction of the RK4 stability limit of convection "
          "and viscosity together (Gershgorin bounds, flow/run_diagnostics.hpp), recomputed "
          "every step, instead of time.cfl and time.fourier; 1 = the largest step the limit "
          "admits (the stability case)");
  s.real("time.steady_tolerance")
      .def(0.0)
      .at_least(0)
      .unit_of("m/s2")
      .doc(
          "> 0: the run stops at a steady state, once max over nodes and components of "
          "|u^{n+1} - u^n| / dt falls below this (before time.end); 0 = run to time.end");
  s.integer("time.max_steps")
      .def(0)
      .at_least(0)
      .unit_of("-")
      .doc("Stop after this many steps even before time.end; 0 = no limit");
  s.choice("time.scheme", flow::time_scheme_names())
      .def("rk4_jameson")
      .unit_of("-")
      .doc(
          "Runge-Kutta predictor (flow/time_scheme.hpp): rk4_jameson, the low-storage stage form "
          "c = 1/4, 1/3, 1/2, 1 (4th order for linear problems, 2nd on the nonlinear equations), "
          "or rk4_classic, the classic 4-stage scheme (1/2, 1/2, 1; weights 1/6, 1/3, 1/3, 1/6); "
          "same stability limit; both measure 2nd order on the 3D Taylor-Green vortex with the "
          "same error (the approximate projection limits them): docs/validation.md, time_order");
  s.boolean("time.project_stages")
      .def(false)
      .unit_of("-")
      .doc(
          "Project every RK stage velocity, not only the end of the step (Sanderse & Koren, J. "
          "Comput. Phys. 231, 2012): three more Poisson solves per step; measured 0.61x the error "
          "at 2.3x the CPU time at equal error (docs/validation.md, time_order)");
  s.boolean("time.land_on_output")
      .def(true)
      .unit_of("-")
      .doc(
          "Shorten a step to land on each field output time (output.interval in s); false = "
          "full steps only, the fields written at the first step at or after each output time, "
          "so that writing fields cannot change the results (e.g. a fixed-dt benchmark)");
  s.real_list("time.land_on")
      .def(std::vector<double>{})
      .at_least(0)
      .unit_of("s")
      .doc(
          "Times the run lands on exactly, in any order: the step before each is shortened as "
          "the steps before time.end are (the last two share what remains when it is less than "
          "two), e.g. the measuring stations of decaying turbulence (validation/cbc_decay); "
          "times at or after time.end do nothing");

  s.section("poisson", "Pressure Poisson solver: hypre PCG preconditioned by BoomerAMG.");
  s.real("poisson.tolerance")
      .def(1e-8)
      .above(0)
      .unit_of("-")
      .doc("Relative residual ||b - A x|| / ||b|| to reach");
  s.integer("poisson.max_iterations")
      .def(200)
      .at_least(1)
      .unit_of("-")
      .doc("PCG iteration cap; reaching it without the tolerance stops the run");
  s.real("poisson.strong_threshold")
      .def(0.25)
      .in_range(0, 1)
      .unit_of("-")
      .doc(
          "BoomerAMG strength threshold (0.25: lower operator complexity and fewer PCG "
          "iterations than hypre's 3D advice 0.5 on our meshes, "
          "validation/notes/flow_throughput.md)");
  // The preconditioner of PCG must be a fixed symmetric positive definite operator: BoomerAMG's
  // V-cycle is one when its restriction is P^T (hypre's default, any interpolation) and its
  // smoother is symmetric (the same on the down and up cycle). The lists keep the values hypre
  // 2.26 documents that meet this on a scalar elliptic matrix.
  s.integer("poisson.coarsen_type")
      .def(10)
      .one_of({0, 1, 3, 6, 7, 8, 9, 10, 11, 21, 22})
      .unit_of("-")
      .doc(
          "BoomerAMG coarsening, hypre numbering: 0 CLJP, 1 Ruge-Stueben, 3 RS + boundary pass, 6 "
          "Falgout, 7 CLJP fixed random, 8 PMIS, 9 PMIS fixed random, 10 HMIS, 11 one-pass RS, 21 "
          "CGC, 22 CGC-E (every documented splitting; the other numbers are none)");
  s.integer("poisson.interp_type")
      .def(6)
      .one_of({0, 3, 4, 5, 6, 7, 8, 9, 12, 13, 14, 16, 17, 18})
      .unit_of("-")
      .doc(
          "BoomerAMG interpolation, hypre numbering: 0 classical, 3 direct, 4/5 multipass, 6 "
          "extended+i, 7 extended+i (no common C), 8/9 standard, 12 FF, 13 FF1, 14 extended, "
          "16-18 matrix-matrix extended forms; refused: 1 (LS, needs GSMG: crashes hypre), 2 (for "
          "hyperbolic PDEs), 10/11 (block, for systems: the Poisson matrix is scalar), 15 (GPU "
          "only)");
  s.integer("poisson.relax_type")
      .def(6)
      .one_of({0, 6, 8, 16, 17, 18})
      .unit_of("-")
      .doc(
          "BoomerAMG smoother (down and up cycle), hypre numbering: 0 Jacobi, 6 hybrid symmetric "
          "Gauss-Seidel, 8 l1 symmetric Gauss-Seidel, 16 Chebyshev, 17 FCF-Jacobi, 18 l1-Jacobi; "
          "PCG needs a symmetric fixed smoother, so refused: forward or backward Gauss-Seidel "
          "(1-4, "
          "13, 14: the V-cycle is not symmetric), 5 (OpenMP chaotic), 9 (Gaussian elimination, "
          "coarsest level only: aborts hypre), 15 (CG, not a fixed operator)");
  s.integer("poisson.aggressive_levels")
      .def(0)
      .in_range(0, 10)
      .unit_of("-")
      .doc("Levels of aggressive coarsening (cheaper set-up, weaker AMG)");
  s.choice("poisson.weights", {"standard", "prism_slab"})
      .def("standard")
      .unit_of("-")
      .doc(
          "Edge weights of the Poisson matrix: standard = the P1 stiffness on all-tetrahedral "
          "meshes, two-point weights on others; prism_slab = the P1 weights extended to slabs of "
          "right prisms (tensor product of the section's P1 stiffness and the 1D axial one; "
          "refused on other cells), for extruded 2D benchmarks such as DFG");
  s.boolean("poisson.periodic_damping")
      .def(false)
      .unit_of("-")
      .doc(
          "The pressure damping term that boundary conditions always switch on, also on fully "
          "periodic meshes: it removes slowly decaying pressure modes of the incremental "
          "projection on irregular tetrahedra (the stability case) at the price of an O(h^2) "
          "pressure error (twice the Taylor-Green central2 error on hexahedra)");
  s.choice("poisson.damping", {"pressure", "increment"})
      .def("pressure")
      .unit_of("-")
      .doc(
          "What the pressure damping term (Rhie-Chow: with boundary conditions, or with "
          "poisson.periodic_damping) acts on. pressure = p^n everywhere: it also removes steady "
          "odd-even pressure modes, but its energy loss hardly falls with dt and it lets a flux "
          "through a loaded immersed wall. increment = half the last increment, (p^n - "
          "p^{n-1})/2, except in the cells with a node on an open boundary (not a wall or "
          "slip), which keep p^n: no flux through the interior in a steady state and a loss "
          "that falls with dt; steady odd-even modes are left as the undamped projection "
          "leaves them (docs/valve.md)");
  s.integer("poisson.print_level")
      .def(0)
      .in_range(0, 3)
      .unit_of("-")
      .doc("hypre's own diagnostic output (0 = none)");

  s.section("initial", "The state at t = 0.");
  s.choice("initial.type", flow::initial_type_names())
      .def("rest")
      .unit_of("-")
      .doc(
          "Fluid at rest, the 2D Taylor-Green vortex ([initial.taylor_green]), whose exact "
          "decay gives the run's error, the 3D Taylor-Green vortex (the same keys; no exact "
          "solution after t = 0: it goes turbulent at Re = U0 L / nu = 1600), or the "
          "divergence-free field u = U0 (sin(z/L), sin(x/L), sin(y/L)) ([initial.cyclic_sines]), "
          "a start with motion in every direction for forced periodic boxes, or Womersley's "
          "pipe flow at t = 0 ([initial.womersley]), or the developed flow of a plane channel "
          "([initial.plane_poiseuille], e.g. the Turek-Hron channel started at its steady inflow)");
  s.section("initial.taylor_green",
            "taylor_green: u = U0 sin(x/L) cos(y/L) F, v = -U0 cos(x/L) sin(y/L) F, w = 0, p = "
            "rho U0^2/4 (cos 2x/L + cos 2y/L) F^2, F = exp(-2 nu t / L^2), Re = U0 L / nu; exact "
            "on a periodic box of side 2 pi L in x and y. taylor_green_3d: u = U0 sin(x/L) "
            "cos(y/L) cos(z/L), v = -U0 cos(x/L) sin(y/L) cos(z/L), w = 0, p = rho U0^2/16 (cos "
            "2x/L + cos 2y/L)(cos 2z/L + 2) at t = 0, on a box periodic in x, y and z.");
  s.when("initial.taylor_green", "initial.type", {"taylor_green", "taylor_green_3d"});
  s.real("initial.taylor_green.velocity")
      .required()
      .above(0)
      .unit_of("m/s")
      .doc("Velocity amplitude U0");
  s.real("initial.taylor_green.length")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Length L: the vortex period is 2 pi L in x and y, measured from the origin");

  s.section("initial.cyclic_sines",
            "u = U0 (sin(z/L), sin(x/L), sin(y/L)), p = 0: divergence-free, periodic on a box of "
            "side 2 pi L.");
  s.when("initial.cyclic_sines", "initial.type", {"cyclic_sines"});
  s.real("initial.cyclic_sines.velocity")
      .required()
      .above(0)
      .unit_of("m/s")
      .doc("Velocity amplitude U0");
  s.real("initial.cyclic_sines.length")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Length L: the period is 2 pi L");

  s.section("initial.womersley",
            "Womersley's exact pipe flow (Womersley 1955, flow/womersley.hpp) at t = 0 for the "
            "flow rate Q(t) = flow_rate + amplitude sin(2 pi t / period + phase): u(r, 0) along "
            "the axis, r from the axis (capped at the radius), with the fluid's viscosity (with a "
            "non-Newtonian flow.viscosity_model, the Newtonian profile of flow.viscosity: a start, "
            "not that fluid's solution).");
  s.when("initial.womersley", "initial.type", {"womersley"});
  s.real("initial.womersley.radius").required().above(0).unit_of("m").doc("Pipe radius");
  s.real("initial.womersley.flow_rate").required().unit_of("m3/s").doc("Mean flow rate");
  s.real("initial.womersley.amplitude")
      .def(0.0)
      .unit_of("m3/s")
      .doc("Amplitude of the sine flow rate");
  s.real("initial.womersley.period").def(1.0).above(0).unit_of("s").doc("Period of the sine");
  s.real("initial.womersley.phase").def(0.0).unit_of("rad").doc("Phase of the sine at t = 0");
  s.real3("initial.womersley.point")
      .def(std::array<double, 3>{0.0, 0.0, 0.0})
      .unit_of("m")
      .doc("A point on the pipe's axis (with pressure = gradient: where p = 0)");
  s.real3("initial.womersley.axis")
      .def(std::array<double, 3>{0.0, 0.0, 1.0})
      .unit_of("-")
      .doc("Direction of the axis and of the flow (normalised)");
  s.choice("initial.womersley.pressure", {"zero", "gradient"})
      .def("zero")
      .unit_of("-")
      .doc(
          "zero: p = 0 (a periodic pipe driven by a body force); gradient: the exact solution's "
          "p = -rho G(0) (x - point) . axis (a pipe between an inlet and a pressure outlet)");

  s.section("initial.plane_poiseuille",
            "The developed plane-channel profile u = 6 U s (1 - s) along `direction`, s = (x - "
            "point) . across / width, 0 outside the channel (0 < s < 1); p = 0. Boundary values "
            "are imposed on it at t = 0.");
  s.when("initial.plane_poiseuille", "initial.type", {"plane_poiseuille"});
  s.real("initial.plane_poiseuille.mean_velocity")
      .required()
      .unit_of("m/s")
      .doc("Mean velocity U over the width (the peak is 1.5 U)");
  s.real("initial.plane_poiseuille.width").required().above(0).unit_of("m").doc("Channel width");
  s.real3("initial.plane_poiseuille.point")
      .def(std::array<double, 3>{0.0, 0.0, 0.0})
      .unit_of("m")
      .doc("A point on the wall at s = 0");
  s.real3("initial.plane_poiseuille.direction")
      .def(std::array<double, 3>{1.0, 0.0, 0.0})
      .unit_of("-")
      .doc("Flow direction (normalised)");
  s.real3("initial.plane_poiseuille.across")
      .def(std::array<double, 3>{0.0, 1.0, 0.0})
      .unit_of("-")
      .doc("Direction across the channel, from the wall at s = 0 (normalised)");

  s.section("output", "Fields written to HDF5 + XDMF (fields.xmf in the run directory).");
  s.real("output.interval")
      .def(0.0)
      .at_least(0)
      .unit_of("s or steps")
      .doc(
          "Write the fields at t = 0, every interval and at the end; 0 = no fields; an interval "
          "in s giving more than 1e5 writes up to time.end is refused");
  s.choice("output.interval_unit", {"s", "steps"})
      .def("s")
      .unit_of("-")
      .doc("Whether output.interval is simulated time or a whole number of time steps");
  s.string_list("output.fields")
      .def(std::vector<std::string>{"velocity", "pressure", "vorticity"})
      .values({"velocity", "pressure", "vorticity", "q_criterion", "sgs_energy_fraction",
               "pope_sgs_fraction"})
      .unit_of("-")
      .doc(
          "Fields to write; vorticity is the curl of the nodal velocity gradient, q_criterion "
          "1/2 (|W|^2 - |S|^2) of it (vortex cores where > 0); with [les] a model, nu_sgs/nu too, "
          "and on request sgs_energy_fraction = k_sgs / (k_res + k_sgs) with Yoshizawa's "
          "k_sgs = (nu_sgs / (0.094 Delta))^2 and k_res the [statistics] k / rho where a section "
          "covers the node (bin with >= 2 samples), else |u|^2 / 2 (les/sgs_energy.hpp), and "
          "pope_sgs_fraction = Pope's a-priori estimate 3/2 C (Delta / (pi L))^(2/3) with C = 1.5 "
          "and L = les.integral_length (les/pope_estimate.hpp); with "
          "immersed structures, their force density (and the Lagrangian meshes in structures/)");
  // Checkpoints for `valsalva run --restart`: HDF5 files in <run dir>/checkpoints (see
  // io/checkpoint.hpp), also written on SIGINT/SIGTERM.
  s.integer("output.checkpoint_every_steps")
      .def(0)
      .at_least(0)
      .unit_of("-")
      .doc(
          "Write a checkpoint (<run dir>/checkpoints, for `valsalva run --restart`) every this "
          "many time steps; 0 = not by step count. With this or checkpoint_every_minutes on, "
          "the run's last step is checkpointed too (extend a finished run with --restart "
          "latest and a later time.end)");
  s.real("output.checkpoint_every_minutes")
      .def(0.0)
      .at_least(0)
      .unit_of("min")
      .doc("Write a checkpoint every this many wall-clock minutes; 0 = not by wall clock");
  s.integer("output.checkpoint_keep")
      .def(2)
      .at_least(1)
      .unit_of("-")
      .doc("Number of newest checkpoints kept; older ones are deleted");
  s.boolean("output.checkpoint_on_signal")
      .def(true)
      .unit_of("-")
      .doc("On SIGINT/SIGTERM write a checkpoint and stop cleanly at the end of the current step");
}

scene::RunOptions flow_run_options(const Scene& scene, const std::filesystem::path& run_dir) {
  scene::RunOptions o;
  const double rho = scene.get<double>("flow.density");
  o.projection.density = rho;
  o.projection.viscosity = scene.get<double>("flow.viscosity") / rho;
  o.projection.rheology = read_viscosity_model(scene);
  o.projection.scheme = flow::parse_convection_kind(scene.get<std::string>("flow.scheme"));
  o.projection.fourth_order_operators = scene.get<bool>("flow.fourth_order_operators");
  o.projection.stiffness_viscous = scene.get<std::string>("flow.viscous_weights") == "stiffness";
  o.velocity_limit = scene.get<double>("flow.velocity_limit");

  o.time.end = scene.get<double>("time.end");
  o.time.dt = scene.get<double>("time.dt");
  o.time.cfl = scene.get<double>("time.cfl");
  o.time.fourier = scene.get<double>("time.fourier");
  o.time.max_steps = scene.get<std::int64_t>("time.max_steps");
  o.projection.time_scheme = flow::parse_time_scheme(scene.get<std::string>("time.scheme"));
  o.projection.project_stages = scene.get<bool>("time.project_stages");
  o.time.land_on_output = scene.get<bool>("time.land_on_output");
  o.time.land_on = scene.get<std::vector<double>>("time.land_on");
  std::sort(o.time.land_on.begin(), o.time.land_on.end());
  o.time.stability_fraction = scene.get<double>("time.stability_fraction");
  o.time.steady_tolerance = scene.get<double>("time.steady_tolerance");

  auto& p = o.projection.poisson;
  p.tolerance = scene.get<double>("poisson.tolerance");
  p.max_iterations = scene.get<int>("poisson.max_iterations");
  p.strong_threshold = scene.get<double>("poisson.strong_threshold");
  p.coarsen_type = scene.get<int>("poisson.coarsen_type");
  p.interp_type = scene.get<int>("poisson.interp_type");
  p.relax_type = scene.get<int>("poisson.relax_type");
  p.aggressive_levels = scene.get<int>("poisson.aggressive_levels");
  p.print_level = scene.get<int>("poisson.print_level");
  o.projection.periodic_pressure_damping = scene.get<bool>("poisson.periodic_damping");
  o.projection.damp_pressure_increment = scene.get<std::string>("poisson.damping") == "increment";
  // The increment form splits the damping by tetrahedra or by edges with non-negative weights
  // (flow/damping_cells.hpp); the slab weights may be negative and have no element split.
  if (o.projection.damp_pressure_increment &&
      scene.get<std::string>("poisson.weights") == "prism_slab")
    throw scene.error("poisson.damping",
                      "damping = \"increment\" cannot be split by cells on the prism_slab weights",
                      "poisson.damping = \"pressure\", or poisson.weights = \"standard\"");
  o.poisson_weights = scene.get<std::string>("poisson.weights") == "prism_slab"
                          ? scene::PoissonWeights::prism_slab
                          : scene::PoissonWeights::standard;

  using flow::InitialType;
  o.initial.type = flow::parse_initial_type(scene.get<std::string>("initial.type"));
  if (o.initial.type == InitialType::taylor_green ||
      o.initial.type == InitialType::taylor_green_3d ||
      o.initial.type == InitialType::cyclic_sines) {
    const std::string table = o.initial.type == InitialType::cyclic_sines ? "initial.cyclic_sines"
                                                                          : "initial.taylor_green";
    o.initial.velocity = scene.get<double>(table + ".velocity");
    o.initial.length = scene.get<double>(table + ".length");
  } else if (o.initial.type == InitialType::womersley) {
    const std::string k = "initial.womersley.";
    auto& ic = o.initial;
    ic.radius = scene.get<double>(k + "radius");
    ic.flow_rate = scene.get<double>(k + "flow_rate");
    ic.amplitude = scene.get<double>(k + "amplitude");
    ic.period = scene.get<double>(k + "period");
    ic.phase = scene.get<double>(k + "phase");
    const auto point = scene.get<std::array<double, 3>>(k + "point");
    const auto axis = scene.get<std::array<double, 3>>(k + "axis");
    ic.point = Eigen::Vector3d(point[0], point[1], point[2]);
    ic.axis = Eigen::Vector3d(axis[0], axis[1], axis[2]);
    if (!(ic.axis.norm() > 0) || !ic.axis.allFinite())
      throw scene.error(k + "axis", "the axis must be a non-zero finite vector");
    ic.pressure_gradient = scene.get<std::string>(k + "pressure") == "gradient";
  } else if (o.initial.type == InitialType::plane_poiseuille) {
    const std::string k = "initial.plane_poiseuille.";
    auto& ic = o.initial;
    auto vec = [&](const std::string& key) {
      const auto a = scene.get<std::array<double, 3>>(k + key);
      const Eigen::Vector3d v(a[0], a[1], a[2]);
      if (key != "point" && (!(v.norm() > 0) || !v.allFinite()))
        throw scene.error(k + key, "the direction must be a non-zero finite vector");
      return v;
    };
    ic.velocity = scene.get<double>(k + "mean_velocity");
    ic.width = scene.get<double>(k + "width");
    ic.point = vec("point");
    ic.axis = vec("direction");
    ic.across = vec("across");
    if (std::abs(ic.axis.normalized().dot(ic.across.normalized())) > 1e-9)
      throw scene.error(k + "across", "across must be perpendicular to the flow direction");
  }
  o.forcing = read_forcing(scene);

  auto& out = o.output;
  out.dir = run_dir;
  out.log_every = scene.get<int>("run.log_every");
  out.interval = scene.get<double>("output.interval");
  out.interval_in_steps = scene.get<std::string>("output.interval_unit") == "steps";
  if (out.interval_in_steps && out.interval != std::floor(out.interval))
    throw scene.error("output.interval", "a step interval must be a whole number of steps",
                      "0, 1, 2, ...");
  // Scenes that would bury a run in output or never end (issue 23): refused up front.
  const double end = o.time.end;
  if (out.interval > 0 && !out.interval_in_steps && end / out.interval > max_field_outputs)
    throw scene.error(
        "output.interval",
        fmt::format("{:g} s writes the fields {:.3g} times up to time.end = {:g} s "
                    "(each write also shortens the time step to land on it)",
                    out.interval, end / out.interval, end),
        fmt::format(">= time.end / {:g} = {:g} s", max_field_outputs, end / max_field_outputs));
  if (const double steps = refused_step_count(o.time, o.time.dt); steps > 0)
    throw scene.error(
        "time.dt",
        fmt::format("{:g} s takes {:.3g} steps to time.end = {:g} s", o.time.dt, steps, end),
        fmt::format(">= time.end / {:g} = {:g} s, or set time.max_steps", max_time_steps,
                    end / max_time_steps));
  const auto fields = scene.get<std::vector<std::string>>("output.fields");
  auto wants = [&](const char* f) {
    return std::find(fields.begin(), fields.end(), f) != fields.end();
  };
  out.velocity = wants("velocity");
  out.pressure = wants("pressure");
  out.vorticity = wants("vorticity");
  out.q_criterion = wants("q_criterion");
  return o;
}

void check_step_count(const Scene& scene, const mesh::DualMetrics& metrics) {
  if (scene.get<double>("time.dt") > 0 || metrics.h.empty()) return;  // fixed dt: checked above
  scene::TimeOptions t;
  t.end = scene.get<double>("time.end");
  t.max_steps = scene.get<std::int64_t>("time.max_steps");
  const double rho = scene.get<double>("flow.density");
  const double fourier = scene.get<double>("time.fourier");
  const double h = *std::min_element(metrics.h.begin(), metrics.h.end());
  // A non-Newtonian fluid: its lowest viscosity over all shear rates, so that dt stays an upper
  // bound (a shear-thinning fluid at rest takes shorter steps than it does while it flows); the
  // cap of a power law with n < 1, which the run's viscous bound takes at every node
  // (flow/viscosity_model.hpp, viscosity_cap).
  const auto model = read_viscosity_model(scene);
  const bool newtonian = model.law == flow::ViscosityLaw::newtonian;
  const double cap = flow::viscosity_cap(model);
  const double mu = cap > 0 ? cap : flow::lowest_viscosity(model);
  if (!(mu > 0)) return;
  // The run's viscous bound max nu dt / h_j^2 <= time.fourier (flow/run_diagnostics.hpp, the
  // same h_j): the first step's dt when a Newtonian fluid starts at rest, an upper bound on
  // every dt since convection and a subgrid viscosity only shorten it.
  const double nu = mu / rho, dt = fourier * h * h / nu;
  const double steps = refused_step_count(t, dt);
  if (steps == 0) return;
  const std::string bound = fmt::format(
      "the viscous bound dt <= time.fourier h^2 / nu = {:g} x ({:.3g} m)^2 / nu = {:.3g} s (h = "
      "the mesh's smallest cube root of a dual volume) takes {:.3g} steps to time.end = {:g} s, "
      "more than {:g}",
      fourier, h, dt, steps, t.end, max_time_steps);
  if (cap > 0)
    throw scene.error(
        "flow.power_law.shear_rate_min",
        fmt::format("{:g} 1/s caps the power law (n = {:g} < 1) at K gamma_min^(n - 1) = {:g} Pa s "
                    "(flow/viscosity_model.hpp, viscosity_cap), the viscosity of every node's "
                    "viscous bound; / flow.density = {:g} kg/m3 gives nu = {:.3g} m2/s: {}",
                    model.shear_rate_min, model.n, mu, rho, nu, bound),
        fmt::format(">= {:.3g} 1/s (a cap <= time.fourier h^2 {:g} flow.density / time.end = "
                    "{:.3g} Pa s), or set time.max_steps",
                    std::pow(fourier * h * h * max_time_steps * rho / t.end / model.consistency,
                             1 / (model.n - 1)),
                    max_time_steps, fourier * h * h * max_time_steps * rho / t.end));
  if (!newtonian)
    throw scene.error(
        "flow.viscosity_model",
        fmt::format("{}: its lowest viscosity {:g} Pa s over all shear rates (flow/"
                    "viscosity_model.hpp, lowest_viscosity) / flow.density = {:g} kg/m3 gives nu "
                    ">= {:.3g} m2/s: {}",
                    flow::viscosity_law_name(model.law), mu, rho, nu, bound),
        fmt::format("a lowest viscosity <= time.fourier h^2 {:g} flow.density / time.end = {:.3g} "
                    "Pa s, or set time.max_steps",
                    max_time_steps, fourier * h * h * max_time_steps * rho / t.end));
  // The message points at the key that departs further from the reference fluid towards a
  // large nu.
  const char* key =
      default_density / rho >= mu / default_viscosity ? "flow.density" : "flow.viscosity";
  throw scene.error(
      key,
      fmt::format("flow.viscosity / flow.density = {:g} Pa s / {:g} kg/m3 gives nu = {:.3g} m2/s: "
                  "{}",
                  mu, rho, nu, bound),
      fmt::format("nu <= time.fourier h^2 {:g} / time.end = {:.3g} m2/s (flow.density >= {:.3g} "
                  "kg/m3 with this viscosity), or set time.max_steps",
                  max_time_steps, fourier * h * h * max_time_steps / t.end,
                  mu * t.end / (fourier * h * h * max_time_steps)));
}

void check_initial_state(const Scene& scene, const mesh::Mesh& mesh) {
  const auto type = flow::parse_initial_type(scene.get<std::string>("initial.type"));
  if (type != flow::InitialType::taylor_green && type != flow::InitialType::taylor_green_3d) return;
  const double length = scene.get<double>("initial.taylor_green.length");
  const double period = 2 * M_PI * length;
  const int axes = type == flow::InitialType::taylor_green ? 2 : 3;
  for (int axis = 0; axis < axes; ++axis) {
    const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
    double found = 0;  // the translation along this axis, 0 if none
    for (const auto& link : mesh.periodic) {
      const Eigen::Vector3d t = link.translation.cwiseAbs();
      if (t[axis] > 0 && t[axis] >= 1e3 * (t.sum() - t[axis])) found = t[axis];
    }
    if (found == 0)
      throw scene.error("initial.taylor_green.length",
                        fmt::format("the Taylor-Green vortex is periodic in {0}, the mesh is not "
                                    "(no periodic pair along {0})",
                                    name),
                        axes == 2 ? "a mesh periodic in x and y" : "a mesh periodic in x, y and z");
    const double k = std::round(found / period);
    if (k < 1 || std::abs(found - k * period) > 1e-9 * found)
      throw scene.error(
          "initial.taylor_green.length",
          fmt::format("{:g} m: the mesh's periodic length in {} is {:.9g} m, not a whole multiple "
                      "of 2 pi L = {:.9g} m, so the vortex is not its exact solution",
                      length, name, found, period),
          fmt::format("L = {:.9g} m / (2 pi k), k = 1, 2, ...", found));
  }
}

}  // namespace valsalva::scene
