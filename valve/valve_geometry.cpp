#include "valve/valve_geometry.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "scene/scene_schema.hpp"

namespace valsalva::valve {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;

double square(double x) {
  return x * x;
}

// Angle in [0, 2 pi).
double wrap(double a) {
  a = std::fmod(a, 2 * pi);
  return a < 0 ? a + 2 * pi : a;
}

std::string key_list() {
  std::string s;
  for (const auto& k : valve_keys()) s += (s.empty() ? "" : ", ") + k.name;
  return s;
}

const ValveKey& find_key(const std::string& name, const std::string& where) {
  const auto& keys = valve_keys();
  const auto it =
      std::find_if(keys.begin(), keys.end(), [&](const ValveKey& k) { return k.name == name; });
  if (it != keys.end()) return *it;
  const auto nearest =
      std::min_element(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
        return scene::edit_distance(name, a.name) < scene::edit_distance(name, b.name);
      });
  throw std::invalid_argument(
      fmt::format("{}: unknown valve key '{}' (did you mean '{}'? keys: {})", where, name,
                  nearest->name, key_list()));
}

// The number in all of `text`, or NaN.
double whole_number(const std::string& text) {
  std::size_t used = 0;
  try {
    const double x = std::stod(text, &used);
    return used == text.size() ? x : std::nan("");
  } catch (const std::exception&) {
    return std::nan("");
  }
}

void require(bool ok, const std::string& key, double value, const std::string& limit) {
  if (!ok)
    throw std::invalid_argument(
        fmt::format("valve key {} = {:g} is refused: {}", key, value, limit));
}

}  // namespace

const std::vector<ValveKey>& valve_keys() {
  using G = ValveGeometry;
  static const std::vector<ValveKey> keys = {
      {"root_diameter", "m", "inflow tract and annulus diameter = frame outer diameter",
       &G::root_diameter},
      {"frame_thickness", "m", "radial thickness of the rigid stent frame", &G::frame_thickness},
      {"ring_height", "m",
       "frame height at the leaflet centres (lowest point of the scalloped attachment)",
       &G::ring_height},
      {"post_height", "m", "frame height at the three commissure posts", &G::post_height},
      {"post_width_deg", "deg", "angular width of each commissure post", &G::post_width_deg},
      {"first_commissure_deg", "deg", "angle of the first commissure (the others +120, +240)",
       &G::first_commissure_deg},
      {"leaflet_radius", "m", "mid-surface radius of the manufactured cylindrical leaflets",
       &G::leaflet_radius},
      {"leaflet_thickness", "m", "leaflet thickness", &G::leaflet_thickness},
      {"leaflet_height", "m", "free edge height above the lowest attachment point",
       &G::leaflet_height},
      {"commissure_attachment", "m",
       "length of each leaflet side attached to a post, below the free edge",
       &G::commissure_attachment},
      {"free_edge_rise", "m",
       "height of the free edge at the leaflet centre above its ends at the posts (parabolic)",
       &G::free_edge_rise},
      {"leaflet_side_element_ratio", "1",
       "width of the leaflet elements at the commissure posts relative to their mean width along "
       "the arc (1: uniform; smaller: the closing leaflets bend from the posts to their "
       "neighbours)",
       &G::leaflet_side_element_ratio},
      {"sinus_height", "m", "height of the sino-tubular junction above the annulus plane",
       &G::sinus_height},
      {"sinus_depth", "m", "largest outward bulge of a sinus lobe (behind a leaflet centre)",
       &G::sinus_depth},
      {"stj_diameter", "m", "diameter of the sino-tubular junction", &G::stj_diameter},
      {"aorta_diameter", "m", "ascending aorta diameter", &G::aorta_diameter},
      {"aorta_transition_length", "m", "length of the cone from the STJ to the aorta",
       &G::aorta_transition_length},
      {"inlet_length", "m", "inflow tract length upstream of the annulus plane", &G::inlet_length},
      {"outlet_length", "m", "distance from the STJ to the outlet plane", &G::outlet_length},
      {"mesh_size", "m",
       "fluid tetrahedron size; leaflet Q2 elements are 1.5 mesh_size along the arc and height",
       &G::mesh_size},
      {"far_mesh_size", "m",
       "fluid tetrahedron size away from the valve region (inflow tract beyond one root radius "
       "upstream of the annulus, aorta beyond one root diameter above the STJ); 0: mesh_size "
       "everywhere",
       &G::far_mesh_size},
  };
  return keys;
}

double ValveGeometry::post_width() const {
  return post_width_deg * deg;
}
double ValveGeometry::leaflet_span() const {
  return 2 * pi / 3 - post_width();
}
double ValveGeometry::commissure_angle(int k) const {
  return wrap(first_commissure_deg * deg + k * 2 * pi / 3);
}
double ValveGeometry::leaflet_centre_angle(int i) const {
  return wrap(commissure_angle(i) + pi / 3);
}

double ValveGeometry::frame_top(double theta) const {
  // phi: angle from the nearest commissure below theta, in [0, 120 deg).
  const double phi = std::fmod(wrap(theta - commissure_angle(0)), 2 * pi / 3);
  const double w2 = post_width() / 2;
  if (phi <= w2 || phi >= 2 * pi / 3 - w2) return post_height;
  const double q = (phi - pi / 3) / (leaflet_span() / 2);
  return ring_height + (free_edge_z() - commissure_attachment - ring_height) * q * q;
}

double ValveGeometry::wall_radius(double theta, double z) const {
  const double R = root_radius();
  if (z <= ring_height || z >= sinus_height) return z >= sinus_height ? stj_diameter / 2 : R;
  double base = R;
  if (z > post_height)
    base += (stj_diameter / 2 - R) *
            square(std::sin(pi / 2 * (z - post_height) / (sinus_height - post_height)));
  const double phi = std::fmod(wrap(theta - commissure_angle(0)), 2 * pi / 3);
  const double w2 = post_width() / 2;
  if (phi <= w2 || phi >= 2 * pi / 3 - w2) return base;
  const double zt = frame_top(theta);
  if (z <= zt) return base;
  const double lobe = square(std::sin(pi * (phi - w2) / leaflet_span()));
  const double eta = (z - zt) / (sinus_height - zt);
  return base + sinus_depth * lobe * square(std::sin(pi * eta));
}

void validate(const ValveGeometry& g) {
  for (const auto& k : valve_keys()) {
    const double v = g.*k.field;
    require(std::isfinite(v), k.name, v, "it must be a finite number");
    if (k.name != "first_commissure_deg" && k.name != "free_edge_rise" && k.name != "far_mesh_size")
      require(v > 0, k.name, v, "it must be positive");
  }
  require(g.free_edge_rise >= 0, "free_edge_rise", g.free_edge_rise, "it must not be negative");
  require(g.leaflet_side_element_ratio <= 1, "leaflet_side_element_ratio",
          g.leaflet_side_element_ratio, "it must be in (0, 1]");
  require(g.far_mesh_size == 0 || g.far_mesh_size >= g.mesh_size, "far_mesh_size", g.far_mesh_size,
          fmt::format("it must be 0 (uniform) or at least mesh_size = {:g} m", g.mesh_size));
  require(g.far_mesh_size <= g.root_radius(), "far_mesh_size", g.far_mesh_size,
          fmt::format("must not exceed the root radius {:g} m", g.root_radius()));
  const double R = g.root_radius();
  require(g.frame_thickness < R, "frame_thickness", g.frame_thickness,
          fmt::format("the frame must be thinner than the root radius {:g} m", R));
  require(g.post_width_deg < 60, "post_width_deg", g.post_width_deg,
          "posts must leave room for the leaflets (< 60 deg)");
  require(g.leaflet_thickness < g.frame_thickness, "leaflet_thickness", g.leaflet_thickness,
          fmt::format("the leaflet must sit on the frame's top edge: thinner than "
                      "frame_thickness = {:g} m",
                      g.frame_thickness));
  const double r_lo = R - g.frame_thickness + g.leaflet_thickness / 2;
  require(g.leaflet_radius >= r_lo && g.leaflet_radius <= R, "leaflet_radius", g.leaflet_radius,
          fmt::format("the leaflet must be attached on the frame's top edge: radius in [{:g}, "
                      "{:g}] m (root radius minus frame thickness plus half the leaflet, root "
                      "radius)",
                      r_lo, R));
  require(g.leaflet_height > g.leaflet_thickness, "leaflet_height", g.leaflet_height,
          fmt::format("must exceed leaflet_thickness = {:g} m", g.leaflet_thickness));
  require(g.free_edge_z() <= g.post_height, "leaflet_height", g.leaflet_height,
          fmt::format("the leaflet is taller than the posts: ring_height + leaflet_height = {:g} "
                      "m must not exceed post_height = {:g} m",
                      g.free_edge_z(), g.post_height));
  require(g.commissure_attachment < g.leaflet_height, "commissure_attachment",
          g.commissure_attachment,
          fmt::format("must be below leaflet_height = {:g} m (the scallop must rise to the posts)",
                      g.leaflet_height));
  require(g.sinus_height > g.post_height, "sinus_height", g.sinus_height,
          fmt::format("the sino-tubular junction must lie above the posts (post_height = {:g} m)",
                      g.post_height));
  require(g.sinus_depth < R, "sinus_depth", g.sinus_depth,
          fmt::format("must be below the root radius {:g} m", R));
  require(g.outlet_length > g.aorta_transition_length, "outlet_length", g.outlet_length,
          fmt::format("must exceed aorta_transition_length = {:g} m", g.aorta_transition_length));
  require(g.mesh_size <= g.leaflet_height, "mesh_size", g.mesh_size,
          fmt::format("must not exceed leaflet_height = {:g} m", g.leaflet_height));
  require(g.mesh_size <= R, "mesh_size", g.mesh_size,
          fmt::format("must not exceed the root radius {:g} m", R));
}

ValveGeometry parse_valve_settings(const std::vector<std::string>& settings) {
  ValveGeometry g;
  std::map<std::string, std::string> seen;
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument(
          fmt::format("make-valve: --set '{}' is not of the form key=value", s));
    const std::string name = s.substr(0, eq), text = s.substr(eq + 1);
    const ValveKey& key = find_key(name, "make-valve --set");
    if (!seen.emplace(name, text).second)
      throw std::invalid_argument(fmt::format("make-valve: key '{}' is set twice", name));
    const double v = whole_number(text);
    if (std::isnan(v))
      throw std::invalid_argument(fmt::format(
          "make-valve: --set {}={}: the value is not a number ({})", name, text, key.unit));
    g.*key.field = v;
  }
  validate(g);
  return g;
}

void write_valve_toml(const std::filesystem::path& file, const ValveGeometry& g) {
  std::FILE* f = std::fopen(file.string().c_str(), "w");
  if (!f) throw std::runtime_error(fmt::format("{}: cannot write the file", file.string()));
  fmt::print(f,
             "# Valve geometry written by `valsalva make-valve` (docs/valve.md); SI units.\n"
             "[valve]\n");
  for (const auto& k : valve_keys())
    fmt::print(f, "{} = {:.17g}  # [{}] {}\n", k.name, g.*k.field, k.unit, k.doc);
  const bool ok = std::fclose(f) == 0;
  if (!ok) throw std::runtime_error(fmt::format("{}: writing the file failed", file.string()));
}

ValveGeometry read_valve_toml(const std::filesystem::path& file) {
  const std::string where = file.string();
  toml::table root;
  try {
    root = toml::parse_file(where);
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(fmt::format("{}: {}", where, e.description()));
  }
  const toml::table* t = root["valve"].as_table();
  if (!t) throw std::invalid_argument(fmt::format("{}: no [valve] table", where));
  ValveGeometry g;
  for (const auto& [name, node] : *t) {
    const ValveKey& key = find_key(std::string(name.str()), where + " [valve]");
    const auto v = node.value<double>();
    if (!v)
      throw std::invalid_argument(fmt::format("{}: [valve] {} is not a number", where, name.str()));
    g.*key.field = *v;
  }
  try {
    validate(g);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", where, e.what()));
  }
  return g;
}

}  // namespace valsalva::valve
