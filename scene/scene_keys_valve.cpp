#include "scene/scene_keys_valve.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "scene/scene_keys.hpp"
#include "scene/scene_keys_boundary.hpp"

namespace valsalva::scene {

void declare_valve_keys(Schema& s) {
  s.section("valve",
            "Indices of a heart valve whose leaflets are one immersed structure with node sets "
            "leaflet1..leaflet3 (the meshes of `valsalva make-valve` and `close-leaflets`): per "
            "sample a row of valve.csv (flow through the inlet and outlet patches, TPG, "
            "geometric orifice area and opening ratio, the three leaflet tips, the largest von "
            "Mises stress and where, the smallest leaflet gap and the contact area) and per "
            "completed cycle a row of valve_cycles.csv (TPG_max and TPG_min, forward, "
            "regurgitant, closing and leakage volumes, opening, fully-open and closing "
            "instants); docs/valve.md.");
  s.string("valve.structure")
      .def("")
      .unit_of("-")
      .doc("The [structure.<name>] holding the leaflets; empty = no valve indices");
  s.real3("valve.axis_point")
      .def(std::array{0.0, 0.0, 0.0})
      .unit_of("m")
      .doc("A point of the valve axis in the annulus plane (make-valve: the origin)");
  s.real3("valve.axis")
      .def(std::array{0.0, 0.0, 1.0})
      .unit_of("-")
      .doc("Direction of the valve axis, pointing downstream (forward flow)");
  s.real("valve.annulus_radius")
      .def(11.05e-3)
      .above(0)
      .unit_of("m")
      .doc(
          "Radius of the disc the orifice area is measured on (the frame's inner radius; "
          "make-valve's default valve: 12.5 - 1.45 mm)");
  s.real3("valve.tpg_upstream")
      .def(std::array{0.0, 0.0, -0.025})
      .unit_of("m")
      .doc(
          "Centre of the upstream pressure region of the transvalvular pressure gradient "
          "(default: on the axis one root diameter before the annulus plane)");
  s.real3("valve.tpg_downstream")
      .def(std::array{0.0, 0.0, 0.05})
      .unit_of("m")
      .doc(
          "Centre of the downstream region (default: on the axis two root diameters after the "
          "annulus plane, in the ascending aorta past the STJ, where the jet's pressure has "
          "recovered)");
  s.real("valve.tpg_radius")
      .def(3e-3)
      .above(0)
      .unit_of("m")
      .doc("Radius of both pressure regions (volume-weighted mean pressure of their nodes)");
  s.string("valve.inlet_patch")
      .def("inlet")
      .unit_of("-")
      .doc("Patch upstream of the valve (ventricle side)");
  s.string("valve.outlet_patch").def("outlet").unit_of("-").doc("Patch downstream (aorta side)");
  s.real("valve.period").def(1.0).above(0).unit_of("s").doc("Cardiac cycle of valve_cycles.csv");
  s.real("valve.start_time")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc("Start of cycle 0 (samples before it are not in any cycle)");
  s.real("valve.open_fraction")
      .def(0.05)
      .above(0)
      .below(1)
      .unit_of("-")
      .doc(
          "The valve counts as open from the first sample whose opening ratio has risen by this "
          "fraction of the cycle's swing (from its smallest ratio, the closed orifice, to its "
          "largest), and closed again from the first sample after the largest that falls back "
          "to it (fully open: 0.9 of the swing); valve_cycles.csv gives both ends of the swing");
  s.integer("valve.every_steps")
      .def(1)
      .at_least(1)
      .unit_of("-")
      .doc(
          "Sample the valve every this many time steps (each sample computes the orifice area "
          "and the nodal stresses of the leaflets)");
  s.integer("valve.orifice_rings")
      .def(128)
      .at_least(8)
      .at_most(2048)
      .unit_of("-")
      .doc("Radial cells of the orifice area's polar grid (its raster error ~ 1 / rings)");
}

std::optional<analysis::ValveMonitorOptions> read_valve_monitor_options(const Scene& scene,
                                                                        const mesh::Mesh& mesh) {
  analysis::ValveMonitorOptions o;
  o.structure = scene.get<std::string>("valve.structure");
  if (o.structure.empty()) return std::nullopt;
  const auto structures = scene.names("structure");
  if (std::find(structures.begin(), structures.end(), o.structure) == structures.end())
    throw scene.error("valve.structure",
                      fmt::format("there is no [structure.{}] in the scene", o.structure),
                      fmt::format("one of: {}", fmt::join(structures, ", ")));
  auto vec = [&](const std::string& key) {
    const auto a = scene.get<std::array<double, 3>>(key);
    return Eigen::Vector3d(a[0], a[1], a[2]);
  };
  o.axis_point = vec("valve.axis_point");
  o.axis = vec("valve.axis");
  if (!(o.axis.norm() > 0)) throw scene.error("valve.axis", "the axis is zero");
  o.annulus_radius = scene.get<double>("valve.annulus_radius");
  o.tpg_upstream = vec("valve.tpg_upstream");
  o.tpg_downstream = vec("valve.tpg_downstream");
  o.tpg_radius = scene.get<double>("valve.tpg_radius");
  for (const char* key : {"valve.inlet_patch", "valve.outlet_patch"}) {
    const auto patch = scene.get<std::string>(key);
    if (mesh.patch_index(patch) < 0)
      throw scene.error(key, fmt::format("the mesh has no patch '{}'", patch),
                        fmt::format("one of: {}", fmt::join(mesh.patch_names, ", ")));
  }
  o.inlet_patch = scene.get<std::string>("valve.inlet_patch");
  o.outlet_patch = scene.get<std::string>("valve.outlet_patch");
  o.period = scene.get<double>("valve.period");
  // Cycles of valve_cycles.csv are periods of the inlet's waveform: a different period would cut
  // every cycle at another phase.
  for (const auto& b : read_boundary_conditions(scene, mesh)) {
    const auto& w = b.flow_rate;
    if (b.patch != o.inlet_patch || b.type != flow::BoundaryType::inlet ||
        w.kind == flow::Waveform::Kind::constant)
      continue;
    if (std::abs(w.period - o.period) > 1e-9 * o.period)
      throw scene.error("valve.period",
                        fmt::format("{:g} s differs from the period {:g} s of the waveform of "
                                    "boundary.{}",
                                    o.period, w.period, b.patch),
                        fmt::format("{:g}", w.period));
  }
  o.start_time = scene.get<double>("valve.start_time");
  o.open_fraction = scene.get<double>("valve.open_fraction");
  o.every_steps = scene.get<int>("valve.every_steps");
  o.orifice_rings = scene.get<int>("valve.orifice_rings");
  return o;
}

}  // namespace valsalva::scene
