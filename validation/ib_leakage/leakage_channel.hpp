// The closed-valve leakage configuration (issue 6, item 4): a 2D channel (a slab periodic in z)
// of height H between two walls (y = 0, H), closed by a thick membrane of Q2 hexahedra standing
// across it at x = x_m and tethered at both walls (node sets "v0", "v1"); the two ends are
// pressure outlets at p_in (xmin, ramped smoothly from 0) and p_out = 0 (xmax). The membrane
// bulges downstream and holds the pressure difference; whatever flows through the channel in
// the steady state leaks through (or around) the immersed membrane.
// Defaults are the reference configuration of ../shared/design/architecture.md (blood analogue,
// polyurethane leaflet, 100 mmHg closed-phase load); the span H = 10 mm is of the order of a
// leaflet's (12.5 mm radius). The slab depth is depth_cells * h and the membrane has one element
// per h in span and depth (marker spacing h/2, the usual no-leak rule) and one through the
// thickness.
// Used by validation/ib_leakage (the case) and validation/bench/ibm_transfer_cost.cpp.
#pragma once

#include <mpi.h>

#include <memory>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/mesh.hpp"
#include "flow/projection_rk4.hpp"
#include "ibm/immersed_structure.hpp"
#include "structure/material.hpp"
#include "structure/solid_mesh.hpp"
#include "validation/ib_leakage/leakage_setup.hpp"

namespace valsalva::validation {

// Fluid mesh, flow solver, membrane and coupling of one setup, wired together (the flow has the
// immersed body force installed). Built in place: the coupling refers to the local mesh.
struct LeakageChannel {
  LeakageChannel(const LeakageSetup& setup, MPI_Comm comm);

  LeakageSetup setup;
  flow::Mesh mesh;
  flow::DualMetrics metrics;
  flow::LocalMesh local;
  std::shared_ptr<flow::BoundaryConditions> bc;
  std::unique_ptr<flow::ProjectionRK4> flow;
  structure::SolidMesh membrane;
  std::unique_ptr<structure::Material> material;
  std::unique_ptr<ibm::ImmersedStructure> ib;
  std::vector<int> inlet_nodes;  // local nodes where p = p_in is imposed
  int inlet_patch = -1, outlet_patch = -1;

  // p_in at time t: pressure * (10 s^3 - 15 s^4 + 6 s^5), s = t / ramp, during the ramp, then
  // pressure. The load excites the oscillation of the fluid columns on the membrane's spring
  // (period 7-8 ms, barely damped by viscosity); two continuous derivatives at both ends keep
  // the residual small for a long ramp, but the flat membrane is soft at low load, so the start
  // of the ramp excites it too: measured +-10 % of the load after 20 ms (the case averages over
  // a window of the hold instead of waiting for it to decay).
  double inlet_pressure(double t) const;
};

}  // namespace valsalva::validation
