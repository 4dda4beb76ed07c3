// ValveGeometry keys: defaults are valid, every refusal names its key, the value and the limit,
// an unknown key names the nearest key, and valve.toml reads back what was written.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "valve/valve_geometry.hpp"

using namespace valsalva;

namespace {

std::string refusal(const std::vector<std::string>& settings) {
  try {
    valve::parse_valve_settings(settings);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("valve geometry: defaults and derived angles") {
  const valve::ValveGeometry g;
  CHECK_NOTHROW(valve::validate(g));
  CHECK(valve::valve_keys().size() == 21);
  const double deg = M_PI / 180;
  CHECK(g.commissure_angle(0) == doctest::Approx(90 * deg));
  CHECK(g.commissure_angle(2) == doctest::Approx(330 * deg));
  CHECK(g.leaflet_centre_angle(0) == doctest::Approx(150 * deg));
  CHECK(g.leaflet_centre_angle(2) == doctest::Approx(30 * deg));
  // Frame top: the posts, the scallop's lowest point at the leaflet centres, and the scallop's
  // end (free edge minus the commissure attachment) just beside a post.
  CHECK(g.frame_top(90 * deg) == doctest::Approx(g.post_height));
  CHECK(g.frame_top(150 * deg) == doctest::Approx(g.ring_height));
  CHECK(g.frame_top(90 * deg + g.post_width() / 2 + 1e-9) ==
        doctest::Approx(g.free_edge_z() - g.commissure_attachment));
  // Sinus wall: R at the annulus side and on the posts, R + depth at a lobe's widest point
  // (leaflet centre, half-way between the scallop and the STJ), the STJ radius at the STJ.
  const double R = g.root_radius();
  CHECK(g.wall_radius(150 * deg, 1e-3) == doctest::Approx(R));
  CHECK(g.wall_radius(90 * deg, 10e-3) == doctest::Approx(R));
  CHECK(g.wall_radius(150 * deg, 0.5 * (g.ring_height + g.sinus_height)) ==
        doctest::Approx(R + g.sinus_depth));
  CHECK(g.wall_radius(150 * deg, g.sinus_height) == doctest::Approx(g.stj_diameter / 2));
}

TEST_CASE("valve geometry: settings override defaults") {
  const auto g = valve::parse_valve_settings({"mesh_size=3e-3", "inlet_length=0.04"});
  CHECK(g.mesh_size == 3e-3);
  CHECK(g.inlet_length == 0.04);
  CHECK(g.root_diameter == 25e-3);
}

TEST_CASE("valve geometry: bad values are refused naming key, value and limit") {
  struct Bad {
    std::vector<std::string> set;
    std::vector<std::string> words;
  };
  const std::vector<Bad> cases = {
      {{"root_diameter=-1"}, {"root_diameter", "-1", "positive"}},
      {{"mesh_size=0"}, {"mesh_size", "0", "positive"}},
      {{"frame_thickness=0.02"}, {"frame_thickness", "0.02", "root radius"}},
      {{"leaflet_height=0.017"}, {"leaflet_height", "0.017", "taller than the posts"}},
      {{"mesh_size=0.016"}, {"mesh_size", "0.016", "leaflet_height"}},
      {{"leaflet_radius=0.02"}, {"leaflet_radius", "0.02", "frame's top edge"}},
      {{"leaflet_thickness=2e-3"}, {"leaflet_thickness", "0.002", "frame_thickness"}},
      {{"commissure_attachment=0.016"}, {"commissure_attachment", "0.016", "leaflet_height"}},
      {{"sinus_height=0.01"}, {"sinus_height", "0.01", "above the posts"}},
      {{"post_width_deg=70"}, {"post_width_deg", "70", "60 deg"}},
      {{"sinus_depth=0.02"}, {"sinus_depth", "0.02", "root radius"}},
      {{"outlet_length=1e-3"}, {"outlet_length", "0.001", "aorta_transition_length"}},
      {{"aorta_diameter=inf"}, {"aorta_diameter", "inf", "finite"}},
      {{"inlet_length=abc"}, {"inlet_length", "not a number"}},
      {{"mesh_size=1e-3", "mesh_size=2e-3"}, {"mesh_size", "twice"}},
      {{"mesh_size"}, {"key=value"}},
      {{"mesh_size=2e-3", "far_mesh_size=1e-3"}, {"far_mesh_size", "0.001", "at least mesh_size"}},
      {{"far_mesh_size=-1e-3"}, {"far_mesh_size", "-0.001", "at least mesh_size"}},
      {{"far_mesh_size=0.02"}, {"far_mesh_size", "0.02", "root radius"}},
      {{"leaflet_side_element_ratio=1.5"}, {"leaflet_side_element_ratio", "1.5", "(0, 1]"}},
      {{"leaflet_side_element_ratio=0"}, {"leaflet_side_element_ratio", "0", "positive"}},
  };
  for (const auto& c : cases) {
    const std::string msg = refusal(c.set);
    CAPTURE(c.set.front());
    CAPTURE(msg);
    REQUIRE(!msg.empty());
    for (const auto& w : c.words) CHECK(msg.find(w) != std::string::npos);
  }
}

TEST_CASE("valve geometry: an unknown key names the nearest key and lists the keys") {
  const std::string msg = refusal({"mesh_sise=1e-3"});
  CHECK(msg.find("unknown valve key 'mesh_sise'") != std::string::npos);
  CHECK(msg.find("did you mean 'mesh_size'") != std::string::npos);
  CHECK(msg.find("sinus_depth") != std::string::npos);
}

TEST_CASE("valve geometry: valve.toml round trip and bad files") {
  const std::filesystem::path dir = "test_output/valve_toml";
  std::filesystem::create_directories(dir);
  const auto g = valve::parse_valve_settings({"mesh_size=0.7e-3", "sinus_depth=4e-3"});
  valve::write_valve_toml(dir / "valve.toml", g);
  const valve::ValveGeometry r = valve::read_valve_toml(dir / "valve.toml");
  for (const auto& k : valve::valve_keys()) {
    CAPTURE(k.name);
    CHECK(r.*k.field == g.*k.field);  // %.17g round-trips doubles exactly
  }
  {
    std::ofstream bad(dir / "bad.toml");
    bad << "[valve]\nroot_diametr = 0.025\n";
  }
  CHECK_THROWS_WITH_AS(valve::read_valve_toml(dir / "bad.toml"),
                       doctest::Contains("did you mean 'root_diameter'"), std::invalid_argument);
  {
    std::ofstream bad(dir / "tall.toml");
    bad << "[valve]\nleaflet_height = 0.02\n";
  }
  CHECK_THROWS_WITH_AS(valve::read_valve_toml(dir / "tall.toml"),
                       doctest::Contains("tall.toml: valve key leaflet_height"),
                       std::invalid_argument);
}
