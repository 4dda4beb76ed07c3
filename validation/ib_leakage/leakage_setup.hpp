// The closed-valve leakage configuration (issue 6, item 4) of one run: validation/ib_leakage/
// ib_leakage.toml (a 2D channel, a slab periodic in z, of height H between two walls, closed by
// a thick membrane of Q2 hexahedra standing across it at x = x_m and tethered at both walls;
// the ends are a pressure inlet at p_in, ramped smoothly from 0, and a pressure outlet at 0)
// with the sizes below as scene overrides. The membrane bulges downstream and holds the
// pressure difference; whatever flows through the channel in the steady state leaks through
// (or around) the immersed membrane.
// Defaults are the reference configuration of ../shared/design/architecture.md (blood analogue,
// polyurethane leaflet, 100 mmHg closed-phase load); the span H = 10 mm is of the order of a
// leaflet's (12.5 mm radius). The slab depth is depth_cells * h and the membrane has one element
// per h in span and depth (marker spacing h/2, the usual no-leak rule) and one through the
// thickness.
// Used by validation/ib_leakage (the case) and validation/bench/ibm_transfer_cost.cpp.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::validation {

struct LeakageSetup {
  double h = 1e-3;             // fluid mesh size [m]
  double kernel_width = 4.0;   // support width in units of h (Peskin 4-point, RKPM-corrected)
  double thickness = 0.15e-3;  // membrane thickness [m]
  double height = 10e-3;       // channel height = membrane span [m]
  double upstream = 8e-3;      // inlet to membrane [m]
  double downstream = 16e-3;   // membrane to outlet [m]
  int depth_cells = 8;         // slab depth in cells (the kernel must fit in the period)
  double density = 1100, viscosity = 3.6e-3;  // blood analogue: kg/m^3, Pa s
  double G = 2.4e6, K = 1.6e6;                // neo-Hookean leaflet [Pa]
  double pressure = 13332.2;                  // imposed p_in - p_out [Pa] (100 mmHg)
  // Smooth ramp of p_in [s]: a table ramp_<ms>ms.csv next to the scene (10 and 20 ms exist).
  double ramp = 0.02;
  double t_end = 0.04;  // [s]; averages over the last half of the hold
  // Tether stiffness per clamped node = G * h * factor [N/m]: holds the clamped nodes within
  // about 1 % of h under the full load at every h (the node count per wall does not change).
  double tether_factor = 1.0;

  double depth() const { return depth_cells * h; }
  double membrane_x() const { return upstream; }
  double length() const { return upstream + downstream; }
};

// validation/ib_leakage/ib_leakage.toml.
std::filesystem::path leakage_scene();

// The setup as overrides of that scene (`valsalva run ib_leakage.toml --set ...`): the box, the
// fluid, the kernel width, the membrane, its material and tether, the ramp table and time.end.
// Throws std::invalid_argument on a setup the scene cannot run (the kernel wider than the slab,
// a ramp without its table, pressure other than the tables' 100 mmHg).
std::vector<std::string> leakage_overrides(const LeakageSetup& setup);

// Ghost layers of a partition of the channel's fluid mesh on which a kernel of `width` h spreads
// and interpolates (the case's force split, the benchmark's transfers): a marker's support
// reaches floor(width / 2 + 1/2) cells per axis from its nearest (owned) node, breadth-first on
// the edge graph (Manhattan distance on hexahedra), so 3 times that, plus one layer that the
// support must not touch.
int leakage_ghost_layers(double width);

// p_in at time t, as the ramp tables sample it: pressure * (10 s^3 - 15 s^4 + 6 s^5),
// s = t / ramp, during the ramp, then pressure. The load excites the oscillation of the fluid
// columns on the membrane's spring (period 7-8 ms, barely damped by viscosity); two continuous
// derivatives at both ends keep the residual small for a long ramp, but the flat membrane is
// soft at low load, so the start of the ramp excites it too: measured +-10 % of the load after
// 20 ms (the case averages over a window of the hold instead of waiting for it to decay).
double leakage_inlet_pressure(const LeakageSetup& setup, double t);

}  // namespace valsalva::validation
