// The closing preprocessing of the reference study (its "heat treatment"): the manufactured
// open (cylindrical) leaflets are pushed closed by a uniform follower pressure on their aortic
// faces with their attachment curves clamped exactly (Dirichlet, no tether), by the static
// Newton solver with load stepping and pseudo-transient continuation (structure/static_solver).
// The closed shape is then the stress-free reference of the FSI run. With contact on, every pair
// of leaflets is a frictionless contact pair (their aortic and ventricular faces,
// structure/contact.hpp), so the leaflets coapt instead of passing through each other.
// Coaptation::planes keeps each leaflet instead on its side of the two planes through the valve
// axis and its commissures (rigid obstacles): the symmetry planes of a tri-leaflet valve, where
// the leaflets of a symmetric closed valve meet (the symmetry assumption of one-leaflet
// finite-element valve models, here applied to all three leaflets at once). It replaces
// leaflet-leaflet point-to-face contact, whose closest points switch faces where thin leaflets
// coapt and stall Newton (docs/validation.md, valve_closure).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "structure/leaflet_indices.hpp"
#include "structure/orifice_area.hpp"
#include "structure/static_solver.hpp"
#include "structure/valve_frame.hpp"
#include "valve/leaflet_groups.hpp"
#include "valve/leaflet_pairs.hpp"

namespace valsalva::valve {

// How the closing keeps the leaflets apart.
enum class Coaptation {
  none,      // they may pass through each other
  leaflets,  // every pair of leaflets is a contact pair
  planes,    // each leaflet stays on its side of the planes through the axis and its commissures
};

struct ClosingOptions {
  double pressure = 12.4e3;  // [Pa] on the aortic faces, towards the ventricle (93 mmHg)
  double shear_modulus = 2.4e6, bulk_modulus = 1.6e6;  // neo-Hookean [Pa]
  int load_steps = 10;
  double damping = 1e-2;  // pseudo-transient continuation (NewtonOptions::damping)
  double rtol = 1e-6;     // relative residual (thin shells: round-off floor near 1e-7)
  int max_relaxation_steps = 400;
  bool contact = true;                         // false: Coaptation::none whatever `coaptation` says
  Coaptation coaptation = Coaptation::planes;  // the reference valve is three-fold symmetric
  structure::ContactOptions contact_options;
  bool verbose = false;
};

struct FreeEdgeMidpoint {
  int node = -1;
  double radial = 0, axial = 0;  // closed position relative to the valve axis [m]
};

struct ClosingResult {
  structure::NewtonResult newton;
  std::vector<LeafletGroups> leaflets;
  std::vector<FreeEdgeMidpoint> free_edge_midpoints;  // one per leaflet
  LeafletPairsReport pairs;                           // crossings, distance, coaptation height
  structure::OrificeArea orifice;                     // of the closed valve
  structure::StressSummary stress;                    // von Mises over Gauss points
  int max_stress_leaflet = -1;
  double max_stress_to_attachment = 0;  // distance of its largest value to the attachment [m]
  double thickness = 0;                 // mean leaflet thickness of the reference mesh [m]
  double seconds = 0;
};

// Throws std::invalid_argument for a mesh without the leaflet groups (valve/leaflet_groups.hpp)
// or bad options. A solve that does not converge returns newton.converged = false with the
// diagnosis; the indices are then those of the last converged state.
ClosingResult close_leaflets(const structure::SolidMesh& mesh, const structure::ValveFrame& valve,
                             const ClosingOptions& options);

}  // namespace valsalva::valve
