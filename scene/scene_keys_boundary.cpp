// Scene keys of the boundary conditions ([boundary.<patch>], flow/boundary_conditions.hpp) and
// their reader.
#include "scene/scene_keys_boundary.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>

#include "core/numeric_table.hpp"
#include "io/waveform_table.hpp"
#include "mesh/patch_shape.hpp"
#include "scene/scene_keys.hpp"

namespace valsalva::scene {

namespace {

// pressure_inlet and elastance_inlet keys.
void declare_inlet_pressure_keys(Schema& s, const std::string& b) {
  s.choice(b + ".pressure_waveform", {"constant", "sine", "table"})
      .def("constant")
      .unit_of("-")
      .doc(
          "pressure_inlet: p_in(t), constant (pressure), sine (pressure + pressure_amplitude "
          "sin(2 pi t / pressure_period + pressure_phase)) or pressure + a periodic CSV table "
          "(pressure_file)");
  s.when(b + ".pressure_waveform", b + ".type", {"pressure_inlet"});
  const std::string sine = "pressure_inlet sine waveform: ";
  s.real(b + ".pressure_amplitude").required().unit_of("Pa").doc(sine + "amplitude");
  s.real(b + ".pressure_period").required().above(0).unit_of("s").doc(sine + "period");
  s.real(b + ".pressure_phase").def(0.0).unit_of("rad").doc(sine + "phase");
  for (const char* key : {".pressure_amplitude", ".pressure_period", ".pressure_phase"}) {
    s.when(b + key, b + ".type", {"pressure_inlet"});
    s.when(b + key, b + ".pressure_waveform", {"sine"});
  }
  s.string(b + ".pressure_file")
      .required()
      .unit_of("-")
      .doc(
          "pressure_inlet: CSV table of rows 't, p' (s, Pa), relative to the scene file; one "
          "period, linearly interpolated, repeated");
  s.when(b + ".pressure_file", b + ".type", {"pressure_inlet"});
  s.when(b + ".pressure_file", b + ".pressure_waveform", {"table"});

  s.choice(b + ".elastance", {"raised_cosine", "table"})
      .def("raised_cosine")
      .unit_of("-")
      .doc(
          "elastance_inlet: E(t); raised_cosine: E = elastance_min + (elastance_max - "
          "elastance_min) (1 - cos(2 pi s / systole)) / 2 for s = t mod cycle_period < systole, "
          "elastance_min after (flow/elastance.hpp); table: a periodic CSV table (elastance_file)");
  s.when(b + ".elastance", b + ".type", {"elastance_inlet"});
  const std::string curve = "elastance_inlet raised_cosine: ";
  s.real(b + ".elastance_min")
      .required()
      .at_least(0)
      .unit_of("Pa/m3")
      .doc(curve + "diastolic elastance (a human ventricle: about 1e7 Pa/m3 = 0.08 mmHg/mL)");
  s.real(b + ".elastance_max")
      .required()
      .at_least(0)
      .unit_of("Pa/m3")
      .doc(curve + "end-systolic elastance, >= elastance_min (about 3e8 Pa/m3 = 2.3 mmHg/mL)");
  s.real(b + ".cycle_period").required().above(0).unit_of("s").doc(curve + "heart period");
  s.real(b + ".systole")
      .required()
      .above(0)
      .unit_of("s")
      .doc(curve + "duration of the contraction, <= cycle_period");
  for (const char* key : {".elastance_min", ".elastance_max", ".cycle_period", ".systole"}) {
    s.when(b + key, b + ".type", {"elastance_inlet"});
    s.when(b + key, b + ".elastance", {"raised_cosine"});
  }
  s.string(b + ".elastance_file")
      .required()
      .unit_of("-")
      .doc(
          "elastance_inlet: CSV table of rows 't, E' (s, Pa/m3), relative to the scene file; one "
          "period, linearly interpolated, repeated; E >= 0");
  s.when(b + ".elastance_file", b + ".type", {"elastance_inlet"});
  s.when(b + ".elastance_file", b + ".elastance", {"table"});
  s.real(b + ".volume")
      .required()
      .at_least(0)
      .unit_of("m3")
      .doc(
          "elastance_inlet: ventricular volume V at the start of the run (a restart continues its "
          "own)");
  s.real(b + ".rest_volume")
      .def(0.0)
      .at_least(0)
      .unit_of("m3")
      .doc("elastance_inlet: unstressed volume V0 of p = E(t) (V - V0)");
  s.string(b + ".venous_return")
      .def("")
      .unit_of("-")
      .doc(
          "elastance_inlet: an rcr_outlet patch whose distal flow p_d / R_d fills the ventricle "
          "(a closed loop: V + C p_d + the fluid volume is conserved); empty = no filling");
  for (const char* key : {".volume", ".rest_volume", ".venous_return"})
    s.when(b + key, b + ".type", {"elastance_inlet"});
}

// A periodic table of `key` (io/waveform_table.hpp), or one that covers the run; its errors
// under that key.
flow::Waveform read_table(const Scene& scene, const std::string& key) {
  try {
    auto table = io::read_waveform_table(scene.path(key));
    io::check_table_wrap(table, scene.get<double>("time.end"), scene.path(key).string());
    return table;
  } catch (const core::TableError& e) {
    throw scene.error(key, e.what());
  }
}

// The pressure_inlet's and elastance_inlet's settings.
void read_inlet_pressure(const Scene& scene, const std::string& key, flow::BoundarySpec& spec) {
  if (spec.type == flow::BoundaryType::pressure_inlet) {
    const auto waveform = scene.get<std::string>(key + ".pressure_waveform");
    auto& p = spec.inlet_pressure;
    if (waveform == "table") {  // p_in = pressure + the table's p(t)
      p = read_table(scene, key + ".pressure_file");
      const double offset = scene.get<double>(key + ".pressure");
      for (double& q : p.q) q += offset;
      return;
    }
    p.mean = scene.get<double>(key + ".pressure");
    if (waveform == "sine") {
      p.kind = flow::Waveform::Kind::sine;
      p.amplitude = scene.get<double>(key + ".pressure_amplitude");
      p.period = scene.get<double>(key + ".pressure_period");
      p.phase = scene.get<double>(key + ".pressure_phase");
    }
    return;
  }
  auto& e = spec.elastance;
  if (scene.get<std::string>(key + ".elastance") == "table") {
    e.tabulated = true;
    e.table = read_table(scene, key + ".elastance_file");
    if (*std::min_element(e.table.q.begin(), e.table.q.end()) < 0)
      throw scene.error(key + ".elastance_file", "the table has a negative elastance",
                        "E >= 0 in every row");
  } else {
    e.minimum = scene.get<double>(key + ".elastance_min");
    e.maximum = scene.get<double>(key + ".elastance_max");
    e.period = scene.get<double>(key + ".cycle_period");
    e.systole = scene.get<double>(key + ".systole");
    if (e.maximum < e.minimum)
      throw scene.error(key + ".elastance_max",
                        fmt::format("{} is below elastance_min = {}", e.maximum, e.minimum),
                        "elastance_max >= elastance_min");
    if (e.systole > e.period)
      throw scene.error(key + ".systole",
                        fmt::format("{} s is longer than cycle_period = {} s", e.systole, e.period),
                        "0 < systole <= cycle_period");
  }
  spec.volume = scene.get<double>(key + ".volume");
  spec.rest_volume = scene.get<double>(key + ".rest_volume");
  spec.venous_return = scene.get<std::string>(key + ".venous_return");
  if (!spec.venous_return.empty() &&
      (!scene.has("boundary." + spec.venous_return) ||
       scene.get<std::string>("boundary." + spec.venous_return + ".type") != "rcr_outlet"))
    throw scene.error(
        key + ".venous_return",
        fmt::format("'{}' is not an rcr_outlet patch of the scene", spec.venous_return),
        "the name of a [boundary.X] table with type = \"rcr_outlet\"");
}

}  // namespace

void declare_boundary_keys(Schema& s) {
  const std::string b = "boundary.<patch>";
  s.section(b,
            "Boundary condition of one mesh patch (the table name is the patch name, e.g. "
            "[boundary.inlet]); every non-periodic patch needs one, periodic patches take none.");
  s.choice(b + ".type", {"wall", "slip", "inlet", "convective_outlet", "pressure_outlet",
                         "resistance_outlet", "rcr_outlet", "pressure_inlet", "elastance_inlet"})
      .required()
      .unit_of("-")
      .doc(
          "wall: no-slip (u = velocity); slip: zero normal velocity; inlet: flow rate Q(t) with a "
          "profile; convective_outlet: du/dt + U_c du/dn = 0, outflow = inflow; pressure_outlet: "
          "fixed pressure, backflow-stabilised where the flow re-enters; resistance_outlet: "
          "p = pressure + resistance Q; rcr_outlet: three-element Windkessel p = p_d + "
          "resistance Q, capacitance dp_d/dt = Q - p_d / distal_resistance (Q the outward patch "
          "flux; both lumped outlets are pressure outlets coupled implicitly through the "
          "pressure equation, flow/lumped_outlets.hpp; flux, pressure and distal pressure in "
          "outlets.csv every step and in log.csv); pressure_inlet: pressure p_in(t) from "
          "pressure_waveform, velocity free with the inflow stabilisation of pressure outlets on "
          "the whole patch; elastance_inlet: a lumped ventricle p = E(t) (V - rest_volume), "
          "dV/dt = -inflow (+ venous_return), coupled implicitly like the lumped outlets, V in "
          "log.csv and outlets.csv");
  s.real3(b + ".velocity")
      .def(std::array{0.0, 0.0, 0.0})
      .unit_of("m/s")
      .doc("Wall velocity, e.g. a moving lid (tangential to the wall)");
  s.when(b + ".velocity", b + ".type", {"wall"});
  s.choice(b + ".profile", {"flat", "poiseuille", "womersley", "plane_poiseuille"})
      .def("flat")
      .unit_of("-")
      .doc(
          "Inlet velocity profile along the inward normal; poiseuille and womersley assume a "
          "circular section (centre and radius from the patch), refused on a patch whose largest "
          "radius from its centroid exceeds 1.12 times that of a disc of its area (a hexagon is "
          "1.10, a square 1.25); womersley needs waveform = sine; "
          "plane_poiseuille is the parabola between two parallel walls (a 2D or slab channel), "
          "across the direction `across`");
  s.when(b + ".profile", b + ".type", {"inlet"});
  s.real3(b + ".across")
      .required()
      .unit_of("-")
      .doc("plane_poiseuille: direction from one channel wall to the other, e.g. [0, 1, 0]");
  s.when(b + ".across", b + ".profile", {"plane_poiseuille"});
  s.choice(b + ".waveform", {"constant", "sine", "table"})
      .def("constant")
      .unit_of("-")
      .doc(
          "Inlet flow rate Q(t): constant (flow_rate), sine (flow_rate + amplitude sin(2 pi t / "
          "period + phase)) or a periodic CSV table (file)");
  s.when(b + ".waveform", b + ".type", {"inlet"});
  s.real(b + ".flow_rate")
      .required()
      .unit_of("m3/s")
      .doc("Constant or mean inlet flow rate (the discrete patch flux equals Q(t) exactly)");
  s.when(b + ".flow_rate", b + ".type", {"inlet"});
  s.when(b + ".flow_rate", b + ".waveform", {"constant", "sine"});
  s.real(b + ".amplitude").required().unit_of("m3/s").doc("Amplitude of the sine flow rate");
  s.when(b + ".amplitude", b + ".type", {"inlet"});
  s.when(b + ".amplitude", b + ".waveform", {"sine"});
  s.real(b + ".period").required().above(0).unit_of("s").doc("Period of the sine flow rate");
  s.when(b + ".period", b + ".type", {"inlet"});
  s.when(b + ".period", b + ".waveform", {"sine"});
  s.real(b + ".phase").def(0.0).unit_of("rad").doc("Phase of the sine flow rate");
  s.when(b + ".phase", b + ".type", {"inlet"});
  s.when(b + ".phase", b + ".waveform", {"sine"});
  s.string(b + ".file")
      .required()
      .unit_of("-")
      .doc(
          "CSV table of rows 't, Q' (s, m3/s), relative to the scene file; one period from the "
          "first to the last time, linearly interpolated, repeated");
  s.when(b + ".file", b + ".type", {"inlet"});
  s.when(b + ".file", b + ".waveform", {"table"});
  s.real(b + ".ramp")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc(
          "Smooth start from rest: Q(t) times (1 - cos(pi t / ramp)) / 2 for t < ramp (the "
          "Turek-Hron inflow ramp); 0 = the full waveform from t = 0; not with profile = "
          "womersley");
  s.when(b + ".ramp", b + ".type", {"inlet"});
  s.string(b + ".swap_with")
      .def("")
      .unit_of("-")
      .doc(
          "A convective_outlet patch that imposes |Q| inward (flat profile) while Q(t) < 0, this "
          "inlet becoming a convective outlet; empty = no exchange");
  s.when(b + ".swap_with", b + ".type", {"inlet"});
  s.real(b + ".pressure")
      .def(0.0)
      .unit_of("Pa")
      .doc(
          "Fixed pressure of the outlet; resistance_outlet: the pressure p0 at zero flux; "
          "pressure_inlet: the constant p_in, the mean of the sine or a constant added to every "
          "row of the table (pressure_waveform constant, sine or table)");
  s.when(b + ".pressure", b + ".type", {"pressure_outlet", "resistance_outlet", "pressure_inlet"});
  s.real(b + ".resistance")
      .required()
      .above(0)
      .unit_of("Pa s/m3")
      .doc(
          "resistance_outlet: R of p = p0 + R Q (the whole systemic circulation: about 1.3e8 "
          "Pa s/m3 = 1 mmHg s/mL); rcr_outlet: the proximal (characteristic) resistance R_p, "
          "typically 5-10 % of R_p + R_d");
  s.when(b + ".resistance", b + ".type", {"resistance_outlet", "rcr_outlet"});
  s.real(b + ".distal_resistance")
      .required()
      .above(0)
      .unit_of("Pa s/m3")
      .doc(
          "rcr_outlet: distal (peripheral) resistance R_d; R_p + R_d is the outlet's steady "
          "resistance");
  s.when(b + ".distal_resistance", b + ".type", {"rcr_outlet"});
  s.real(b + ".capacitance")
      .required()
      .above(0)
      .unit_of("m3/Pa")
      .doc("rcr_outlet: compliance C (systemic arteries: about 1e-8 m3/Pa = 1.3 mL/mmHg)");
  s.when(b + ".capacitance", b + ".type", {"rcr_outlet"});
  s.real(b + ".distal_pressure")
      .def(0.0)
      .unit_of("Pa")
      .doc("rcr_outlet: distal pressure p_d at the start of the run (a restart continues its own)");
  s.when(b + ".distal_pressure", b + ".type", {"rcr_outlet"});
  s.real(b + ".convection_speed")
      .def(0.0)
      .at_least(0)
      .unit_of("m/s")
      .doc("Convection speed U_c; 0 = total inflow / total outflow area at every stage");
  s.when(b + ".convection_speed", b + ".type", {"convective_outlet"});
  declare_inlet_pressure_keys(s, b);
}

std::vector<flow::BoundarySpec> read_boundary_conditions(const Scene& scene,
                                                         const mesh::Mesh& mesh) {
  std::set<std::string> periodic;
  for (const auto& link : mesh.periodic) periodic.insert({link.master, link.slave});
  const std::string patches = fmt::format("{}", fmt::join(mesh.patch_names, ", "));
  std::vector<flow::BoundarySpec> specs;
  const auto names = scene.names("boundary");
  for (const auto& name : names) {
    const std::string key = "boundary." + name;
    if (mesh.patch_index(name) < 0)
      throw scene.error(key, fmt::format("patch '{}' is not in the mesh", name), patches);
    if (periodic.count(name))
      throw scene.error(key, fmt::format("patch '{}' is periodic (paired by the mesh's periodic "
                                         "links): it takes no boundary condition",
                                         name));
    flow::BoundarySpec spec;
    spec.patch = name;
    const auto type = scene.get<std::string>(key + ".type");
    if (type == "wall") {
      spec.type = flow::BoundaryType::wall;
      const auto v = scene.get<std::array<double, 3>>(key + ".velocity");
      spec.wall_velocity = Eigen::Vector3d(v[0], v[1], v[2]);
    } else if (type == "slip") {
      spec.type = flow::BoundaryType::slip;
    } else if (type == "inlet") {
      spec.type = flow::BoundaryType::inlet;
      const auto profile = scene.get<std::string>(key + ".profile");
      spec.profile = profile == "flat"         ? flow::InletProfile::flat
                     : profile == "poiseuille" ? flow::InletProfile::poiseuille
                     : profile == "womersley"  ? flow::InletProfile::womersley
                                               : flow::InletProfile::plane_poiseuille;
      if (spec.profile == flow::InletProfile::plane_poiseuille) {
        const auto a = scene.get<std::array<double, 3>>(key + ".across");
        spec.across = Eigen::Vector3d(a[0], a[1], a[2]);
        if (!(spec.across.norm() > 0))
          throw scene.error(key + ".across", "must be a nonzero direction", "e.g. [0, 1, 0]");
      }
      if (spec.profile == flow::InletProfile::poiseuille ||
          spec.profile == flow::InletProfile::womersley) {
        const auto shape = mesh::patch_shape(mesh, mesh.patch_index(name));
        if (shape.circularity > mesh::max_circularity)
          throw scene.error(
              key + ".profile",
              fmt::format("the {} profile assumes a circular section, but patch '{}' is not one: "
                          "its largest radius from the centroid, {:.4g} m, is {:.3f} times the "
                          "radius {:.4g} m of a disc of its area {:.4g} m^2 (a disc meshed with "
                          "6 or more sides is below {})",
                          profile, name, shape.max_radius, shape.circularity,
                          shape.max_radius / shape.circularity, shape.area, mesh::max_circularity),
              "\"flat\", or \"plane_poiseuille\" between two parallel walls");
      }
      const auto waveform = scene.get<std::string>(key + ".waveform");
      auto& q = spec.flow_rate;
      if (waveform == "table") {
        q = read_table(scene, key + ".file");
      } else {
        q.mean = scene.get<double>(key + ".flow_rate");
        if (waveform == "sine") {
          q.kind = flow::Waveform::Kind::sine;
          q.amplitude = scene.get<double>(key + ".amplitude");
          q.period = scene.get<double>(key + ".period");
          q.phase = scene.get<double>(key + ".phase");
        }
      }
      q.ramp = scene.get<double>(key + ".ramp");
      if (spec.profile == flow::InletProfile::womersley && q.ramp != 0)
        throw scene.error(key + ".ramp",
                          "the Womersley profile is the periodic state of a sine flow rate, not "
                          "its start from rest",
                          "0 with profile = \"womersley\"");
      if (spec.profile == flow::InletProfile::womersley && waveform != "sine")
        throw scene.error(key + ".profile",
                          "the Womersley profile is the exact solution for a sine flow rate: "
                          "set waveform = \"sine\"",
                          "\"flat\", \"poiseuille\" for other waveforms");
      spec.swap_with = scene.get<std::string>(key + ".swap_with");
      if (!spec.swap_with.empty()) {
        const auto partner = std::find(names.begin(), names.end(), spec.swap_with);
        if (partner == names.end() ||
            scene.get<std::string>("boundary." + spec.swap_with + ".type") != "convective_outlet")
          throw scene.error(
              key + ".swap_with",
              fmt::format("'{}' is not a convective_outlet patch of the scene", spec.swap_with),
              "the name of a [boundary.X] table with type = \"convective_outlet\"");
      }
    } else if (type == "convective_outlet") {
      spec.type = flow::BoundaryType::convective_outlet;
      spec.convection_speed = scene.get<double>(key + ".convection_speed");
    } else if (type == "pressure_outlet") {
      spec.type = flow::BoundaryType::pressure_outlet;
      spec.pressure = scene.get<double>(key + ".pressure");
    } else if (type == "resistance_outlet") {
      spec.type = flow::BoundaryType::resistance_outlet;
      spec.pressure = scene.get<double>(key + ".pressure");
      spec.resistance = scene.get<double>(key + ".resistance");
    } else if (type == "pressure_inlet" || type == "elastance_inlet") {
      spec.type = type == "pressure_inlet" ? flow::BoundaryType::pressure_inlet
                                           : flow::BoundaryType::elastance_inlet;
      read_inlet_pressure(scene, key, spec);
    } else {
      spec.type = flow::BoundaryType::rcr_outlet;
      spec.resistance = scene.get<double>(key + ".resistance");
      spec.distal_resistance = scene.get<double>(key + ".distal_resistance");
      spec.capacitance = scene.get<double>(key + ".capacitance");
      spec.distal_pressure = scene.get<double>(key + ".distal_pressure");
    }
    specs.push_back(std::move(spec));
  }
  // Every non-periodic patch with faces needs a condition.
  std::vector<char> has_faces(mesh.patch_names.size(), 0);
  for (int p : mesh.face_patches) has_faces[p] = 1;
  std::vector<std::string> missing;
  for (std::size_t p = 0; p < mesh.patch_names.size(); ++p) {
    const auto& name = mesh.patch_names[p];
    if (has_faces[p] && !periodic.count(name) &&
        std::find(names.begin(), names.end(), name) == names.end())
      missing.push_back("'" + name + "'");
  }
  if (!missing.empty())
    throw scene.error(
        "boundary",
        fmt::format("mesh patch{} {} {} no boundary condition: add a [boundary.<patch>] table "
                    "with a type for each (or make the patch periodic)",
                    missing.size() > 1 ? "es" : "", fmt::join(missing, ", "),
                    missing.size() > 1 ? "have" : "has"),
        flow::boundary_type_names);
  return specs;
}

}  // namespace valsalva::scene
