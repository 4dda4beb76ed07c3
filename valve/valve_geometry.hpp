// The parametric tri-leaflet valve in its aortic root: every dimension of the root, the rigid
// stent frame and the three manufactured (open, cylindrical) leaflets, as documented keys with
// the reference valve's values as defaults (SI: metres, angles in degrees). docs/valve.md
// describes the shape with a figure-like sketch; the summary:
//
// - Axis z, annulus plane z = 0 (the frame's upstream face, the backward-facing step), flow
//   towards +z. R = root_diameter / 2 is the inflow-tract and annulus radius and the frame's
//   outer radius (the valve's outer diameter equals the root's).
// - Frame (rigid, cut out of the fluid): r in [R - frame_thickness, R], 0 <= z <= z_top(theta).
//   Its top edge is the leaflets' attachment: z_top = post_height on three commissure posts of
//   angular width post_width_deg centred on the commissures (first_commissure_deg + k 120 deg);
//   between two posts it is the scallop z_a(q) = ring_height + (z_free - commissure_attachment
//   - ring_height) q^2, q in [-1, 1] across the leaflet, so the frame is a base ring of height
//   ring_height at the leaflet centres that rises along the scallop to the posts.
// - Leaflets (manufactured shape): patches of the cylinder r = leaflet_radius (mid-surface), one
//   between each pair of posts (span 120 deg - post width), bounded below by the scallop, along
//   their sides by the posts over commissure_attachment, and above by the free edge at
//   z_free = ring_height + leaflet_height <= post_height. The validation case leaflet_closure
//   uses the same generator (valve/leaflet_mesh.hpp).
// - Lumen: the inflow tract r = R for -inlet_length <= z; the sinuses of Valsalva from the
//   frame's top edge up to the sino-tubular junction (STJ) at z = sinus_height; a cone to the
//   ascending aorta over aorta_transition_length; the aorta up to z = sinus_height +
//   outlet_length. Sinus wall (an equivalent documented parametrisation of the three-lobed
//   shape of Reul et al., J. Biomech. 23 (1990) 181, who describe the root by its annulus,
//   sinus and STJ diameters and the sinus height):
//     r_wall(theta, z) = R_b(z) + sinus_depth L(theta) b(eta),
//     L = sin^2(pi (phi - w/2) / (120 deg - w)) on a leaflet's span (phi from the commissure,
//     w the post width), 0 on the posts: one lobe behind each leaflet;
//     eta = (z - z_top(theta)) / (sinus_height - z_top(theta)) in [0, 1], b = sin^2(pi eta):
//     the lobe leaves the wall at the leaflet's attachment, tangent to the frame's outer face,
//     bulges most half-way up and returns to the STJ circle;
//     R_b = R below the post tops, rising as sin^2 to stj_diameter / 2 at the STJ.
// - Fluid sizes: mesh_size in the valve region (the leaflets and their kernels must be resolved
//   there), far_mesh_size (coarser, optional) in the inflow tract and the aorta away from it,
//   with a transition of two far sizes (a Gmsh Box field).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::valve {

struct ValveGeometry {
  double root_diameter = 25e-3;
  double frame_thickness = 1.45e-3;
  double ring_height = 1e-3;
  double post_height = 17e-3;
  double post_width_deg = 10;
  double first_commissure_deg = 90;
  double leaflet_radius = 12.5e-3;
  double leaflet_thickness = 0.15e-3;
  double leaflet_height = 15e-3;
  double commissure_attachment = 2e-3;
  double free_edge_rise = 5e-3;
  double leaflet_side_element_ratio = 0.3;
  double sinus_height = 18e-3;
  double sinus_depth = 4.5e-3;
  double stj_diameter = 28e-3;
  double aorta_diameter = 31e-3;
  double aorta_transition_length = 6e-3;
  double inlet_length = 50e-3;
  double outlet_length = 92e-3;
  double mesh_size = 1e-3;
  double far_mesh_size = 0;  // 0: the whole fluid at mesh_size

  // The fluid size away from the valve region (see refined_region_* below).
  double fluid_far_size() const { return far_mesh_size > 0 ? far_mesh_size : mesh_size; }
  // The valve region meshed at mesh_size when far_mesh_size is coarser: the whole root cross-
  // section, from one root radius upstream of the annulus (the frame's step and the inflow's
  // contraction onto the leaflets) to one root diameter above the STJ (the jet's near wake).
  double refined_region_z_min() const { return -root_radius(); }
  double refined_region_z_max() const { return sinus_height + root_diameter; }
  double refined_region_radius() const { return root_radius() + sinus_depth; }

  // Derived quantities.
  double root_radius() const { return root_diameter / 2; }
  double free_edge_z() const { return ring_height + leaflet_height; }
  double post_width() const;                 // [rad]
  double leaflet_span() const;               // angle between two posts [rad]
  double commissure_angle(int k) const;      // [rad], k = 0, 1, 2
  double leaflet_centre_angle(int i) const;  // [rad], midway between commissures i and i+1
  // Frame height at angle theta: post_height on a post, the scallop between posts.
  double frame_top(double theta) const;
  // Lumen radius at (theta, z) for z in the sinus region, R below it (see the header comment).
  double wall_radius(double theta, double z) const;
  double inlet_z() const { return -inlet_length; }
  double outlet_z() const { return sinus_height + outlet_length; }
};

// One documented key: name, default (from ValveGeometry{}), unit and meaning.
struct ValveKey {
  std::string name, unit, doc;
  double ValveGeometry::*field;
};
const std::vector<ValveKey>& valve_keys();

// Throws std::invalid_argument naming the key, the value and the limit for a value that is not
// finite or not positive, a frame thicker than the root radius, a free edge above the posts, a
// mesh size above the leaflet height, and the other limits listed in docs/valve.md.
void validate(const ValveGeometry& g);

// Applies "key=value" settings (--set) to the defaults and validates the result. An unknown key
// is refused with the list of keys and the nearest one; a value that is not a number, or a key
// set twice, is refused naming the key.
ValveGeometry parse_valve_settings(const std::vector<std::string>& settings);

// valve.toml: the resolved parameters, one key per line (table [valve]), read back by
// read_valve_toml (missing keys take their defaults; unknown keys are refused; the result is
// validated). Errors name the file.
void write_valve_toml(const std::filesystem::path& file, const ValveGeometry& g);
ValveGeometry read_valve_toml(const std::filesystem::path& file);

}  // namespace valsalva::valve
