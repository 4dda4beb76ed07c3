// Good scenes: typed getters, defaults, user-named tables, locations, and the resolved scene
// round trip; the schema machinery (wildcards, conditions, float lists and tables) on a small
// schema of its own.
#include <doctest/doctest.h>

#include <filesystem>

#include "flow/convection_scheme.hpp"
#include "flow/initial_condition.hpp"
#include "flow/projection_rk4.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/local_mesh.hpp"
#include "scene/scene.hpp"
#include "structure/material.hpp"

namespace fs = std::filesystem;
using namespace valsalva;

namespace {
const fs::path data = fs::path(VALSALVA_SOURCE_DIR) / "tests/data/scenes";

std::string error_of(std::string_view text, const scene::Schema& schema = scene::scene_schema()) {
  try {
    scene::parse_scene(text, "t.toml", schema);
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST_CASE("a box scene with every key set reads back what the file says") {
  const scene::Scene s = scene::load_scene(data / "box.toml");
  CHECK(s.get<std::string>("run.output_dir") == "runs/box_test");
  CHECK(s.get<bool>("run.overwrite"));
  CHECK(s.get<int>("run.log_every") == 20);
  CHECK(s.get<std::string>("mesh.source") == "box");
  CHECK(s.get<double>("mesh.scale") == 1.0);  // integer 1 accepted for a float
  CHECK(s.get<std::array<double, 3>>("mesh.box.origin") == std::array{-0.5, 0.0, 0.25});
  CHECK(s.get<std::array<double, 3>>("mesh.box.length") == std::array{1.0, 2.0, 0.5});
  CHECK(s.get<std::array<int, 3>>("mesh.box.cells") == std::array{4, 8, 2});
  CHECK(s.get<std::string>("mesh.box.cell_type") == "tetra");
  CHECK(s.get<double>("mesh.box.perturbation") == 0.2);
  CHECK(s.get<std::int64_t>("mesh.box.seed") == 7);
  CHECK(s.get<std::vector<std::string>>("mesh.box.periodic") == std::vector<std::string>{"x", "z"});
  CHECK(s.get<int>("partition.ghost_layers") == 3);
  CHECK(s.get<std::string>("partition.method") == "block");
  CHECK_FALSE(s.has("mesh.pipe.radius"));  // switched off by mesh.source = "box"
  CHECK_FALSE(s.has("mesh.file"));
  const scene::Location at = s.location("mesh.box.cells");
  CHECK(at.file == (data / "box.toml").string());
  CHECK(at.line == 14);
  CHECK(at.column == 1);
}

TEST_CASE("defaults fill every key the file leaves out") {
  const scene::Scene s = scene::load_scene(data / "pipe.toml");
  CHECK(s.get<double>("mesh.pipe.radius") == 0.0125);
  CHECK(s.get<double>("mesh.pipe.size") == 1.0e-3);
  CHECK(s.get<std::string>("run.output_dir").empty());
  CHECK_FALSE(s.get<bool>("run.overwrite"));
  CHECK(s.get<int>("run.log_every") == 10);
  CHECK(s.get<double>("mesh.scale") == 1.0);
  CHECK(s.get<int>("partition.ghost_layers") == 2);
  CHECK(s.get<std::string>("partition.method") == "metis");
  CHECK_FALSE(s.has("mesh.box.cells"));
  CHECK(s.is_set("mesh.pipe.radius"));
  CHECK_FALSE(s.is_set("partition.method"));
  // A defaulted key points at its nearest written table, or the first line.
  CHECK(s.location("partition.method").line == 1);
  CHECK(s.location("mesh.pipe.size").line == 8);
  CHECK(s.location("mesh.pipe.size").column == 1);

  const scene::Scene b = scene::parse_scene("[mesh]\nsource = \"box\"\n", "b.toml");
  CHECK(b.get<std::array<int, 3>>("mesh.box.cells") == std::array{8, 8, 8});
  CHECK(b.get<std::array<double, 3>>("mesh.box.length") == std::array{1.0, 1.0, 1.0});
  CHECK(b.get<std::string>("mesh.box.cell_type") == "hexa");
  CHECK(b.get<std::vector<std::string>>("mesh.box.periodic").empty());
}

TEST_CASE("user-named tables, file paths and errors raised by other modules") {
  const scene::Scene s = scene::load_scene(data / "gmsh_periodic.toml");
  CHECK(s.names("mesh.periodic") == std::vector<std::string>{"spanwise", "streamwise"});
  CHECK(s.names("boundary").empty());
  CHECK(s.get<std::string>("mesh.periodic.streamwise.slave") == "outlet");
  CHECK(s.get<std::array<double, 3>>("mesh.periodic.spanwise.translation") ==
        std::array{0.0, 0.0, 0.02});
  CHECK(s.path("mesh.file") == (data / "meshes/channel.msh").lexically_normal());
  CHECK(s.get<double>("mesh.scale") == 0.001);

  const scene::SceneError e = s.error("mesh.periodic.spanwise.master",
                                      "patch 'front' is not in the mesh", "inlet, outlet, wall");
  CHECK(std::string(e.what()) == (data / "gmsh_periodic.toml").string() +
                                     ":8:1: key 'mesh.periodic.spanwise.master': patch 'front' is "
                                     "not in the mesh (accepted: inlet, outlet, wall)");
  CHECK_THROWS_AS(s.get<double>("mesh.periodic.spanwise.master"), std::logic_error);
  CHECK_THROWS_AS(s.get<double>("flow.no_such_key"), std::logic_error);
  CHECK_THROWS_AS(s.get<double>("mesh.pipe.radius"), std::logic_error);
}

TEST_CASE("the resolved scene parses back to the same scene") {
  for (const char* name : {"box.toml", "pipe.toml", "gmsh_periodic.toml"}) {
    const std::string label = name;
    CAPTURE(label);
    const scene::Scene s = scene::load_scene(data / name);
    const scene::Scene again = scene::parse_scene(s.resolved(), data / "resolved.toml");
    CHECK(again.table() == s.table());
    // Nothing left to fill: resolving a resolved scene changes nothing.
    for (const auto& key : scene::scene_schema().keys())
      if (key.pattern.find('*') == std::string::npos && s.has(key.path))
        CHECK(again.is_set(key.path));
  }
  const scene::Scene s = scene::load_scene(data / "pipe.toml");
  const std::string text = s.resolved();
  CHECK(text.find("log_every = 10") != std::string::npos);
  CHECK(text.find("size = 0.001") != std::string::npos);
  CHECK(text.find("method = 'metis'") != std::string::npos);
}

TEST_CASE("every ready-to-run scene in scenes/ is valid") {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(VALSALVA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    const std::string name = entry.path().string();
    CAPTURE(name);
    CHECK_NOTHROW(scene::load_scene(entry.path()));
    ++count;
  }
  CHECK(count >= 1);
}

TEST_CASE("schema machinery: wildcards, conditions, float lists and tables") {
  scene::Schema schema;
  schema.section("boundary.<patch>", "Boundary condition of one patch.");
  schema.choice("boundary.<patch>.type", {"wall", "velocity_inlet", "outlet"})
      .required()
      .unit_of("-")
      .doc("Kind of condition");
  schema.real3("boundary.<patch>.velocity")
      .def(std::array{0.0, 0.0, 0.0})
      .unit_of("m/s")
      .doc("Inlet velocity");
  schema.when("boundary.<patch>.velocity", "boundary.<patch>.type", {"velocity_inlet"});
  schema.section("waveform", "Flow-rate waveform.");
  schema.real_list("waveform.times")
      .required()
      .at_least(0)
      .at_least_size(2)
      .unit_of("s")
      .doc("Sample times");
  schema.real_table("waveform.gains")
      .def(std::map<std::string, double>{{"a", 1.0}})
      .above(0)
      .unit_of("-")
      .doc("Gains");
  schema.check();

  const scene::Scene s = scene::parse_scene(R"(
[waveform]
times = [0, 0.5, 1.0]
gains = { up = 2.0, down = 0.5 }
[boundary.wall_1]
type = "wall"
[boundary.in]
type = "velocity_inlet"
velocity = [0, 0, 0.3]
)",
                                            "w.toml", schema);
  CHECK(s.names("boundary") == std::vector<std::string>{"wall_1", "in"});
  CHECK(s.get<std::array<double, 3>>("boundary.in.velocity") == std::array{0.0, 0.0, 0.3});
  CHECK_FALSE(s.has("boundary.wall_1.velocity"));  // only inlets have a velocity
  CHECK(s.get<std::vector<double>>("waveform.times") == std::vector{0.0, 0.5, 1.0});
  CHECK(s.get<std::map<std::string, double>>("waveform.gains") ==
        std::map<std::string, double>{{"down", 0.5}, {"up", 2.0}});

  const std::string wall_velocity = error_of(
      "[waveform]\ntimes = [0, 1]\n[boundary.w]\ntype = \"wall\"\nvelocity = [1, 0, 0]\n", schema);
  CHECK(wall_velocity ==
        "t.toml:5:1: key 'boundary.w.velocity': has no effect because boundary.w.type = \"wall\" "
        "(accepted: only when boundary.w.type is \"velocity_inlet\")");
  CHECK(error_of("[waveform]\ntimes = [0, 1]\n[boundary.w]\n", schema) ==
        "t.toml:3:11: key 'boundary.w.type': required key is missing; expected a string "
        "(accepted: \"wall\", \"velocity_inlet\", \"outlet\")");
  CHECK(error_of("[waveform]\ntimes = [1]\n", schema) ==
        "t.toml:2:9: key 'waveform.times': expected an array of numbers, got 1 values "
        "(accepted: at least 2 values, each >= 0)");
  CHECK(error_of("[waveform]\ntimes = [0, 1]\ngains = { up = -1 }\n", schema) ==
        "t.toml:3:16: key 'waveform.gains.up': value -1 is out of range (accepted: each > 0)");
  CHECK(error_of("[waveform]\ntimes = [0, 1]\n[boundary.w]\ntype = \"wal\"\n", schema) ==
        "t.toml:4:8: key 'boundary.w.type': unknown value \"wal\"; did you mean \"wall\"? "
        "(accepted: \"wall\", \"velocity_inlet\", \"outlet\")");
  CHECK(error_of("[waveform]\ntimes = [0, 1]\n[boundary.w]\ntype = \"wall\"\nvelocty = 1\n",
                 schema) ==
        "t.toml:5:1: key 'boundary.w.velocty': unknown key; did you mean 'boundary.w.velocity'? "
        "(accepted: keys type, velocity)");
}

TEST_CASE("numbers that do not fit, non-finite floats and repeated directions are refused") {
  CHECK(error_of("[mesh]\nsource = \"box\"\n[mesh.box]\ncells = [8, 3000000000, 8]\n") ==
        "t.toml:4:13: key 'mesh.box.cells': element 2 is 3000000000, does not fit a 32-bit integer "
        "(accepted: 3 values, each >= 1)");
  CHECK(error_of("[mesh]\nsource = \"box\"\nscale = nan\n") ==
        "t.toml:3:9: key 'mesh.scale': value nan is not a finite number (accepted: > 0)");
  CHECK(error_of("[mesh]\nsource = \"box\"\n[mesh.box]\nperiodic = [\"y\", \"y\"]\n") ==
        "t.toml:4:18: key 'mesh.box.periodic': element 2: \"y\" is repeated "
        "(accepted: each of \"x\", \"y\", \"z\", no repeats)");
  CHECK(error_of("[mesh]\nsource = \"box\"\nsource = \"pipe\"\n")
            .rfind("t.toml:3:10: TOML syntax error: ", 0) == 0);  // a key written twice
  CHECK(scene::format_value(scene::KeyValue{std::map<std::string, double>{
            {"a b", 1.0}, {"c", 2.5}}}) == "{ \"a b\" = 1.0, c = 2.5 }");
}

TEST_CASE("bad declarations are refused when the schema is checked") {
  scene::Schema no_default;
  no_default.section("a", "A.");
  no_default.real("a.x").unit_of("m").doc("x");
  CHECK_THROWS_WITH_AS(no_default.check(),
                       "scene schema: key 'a.x': needs exactly one of a default or required()",
                       std::logic_error);
  scene::Schema bad_default;
  bad_default.section("a", "A.");
  bad_default.integer("a.n").def(0).at_least(1).unit_of("-").doc("n");
  CHECK_THROWS_AS(bad_default.check(), std::logic_error);
  scene::Schema twice;
  twice.section("a", "A.");
  twice.real("a.x").def(1.0).unit_of("m").doc("x");
  twice.real("a.x").def(2.0).unit_of("m").doc("x");
  CHECK_THROWS_WITH_AS(twice.check(), "scene schema: key 'a.x': declared twice", std::logic_error);
  scene::Schema no_section;
  no_section.real("b.x").def(1.0).unit_of("m").doc("x");
  CHECK_THROWS_AS(no_section.check(), std::logic_error);
  CHECK_NOTHROW(scene::scene_schema().check());
}

TEST_CASE("edit distance") {
  CHECK(scene::edit_distance("cels", "cells") == 1);
  CHECK(scene::edit_distance("partiton", "partition") == 1);
  CHECK(scene::edit_distance("kitten", "sitting") == 3);
  CHECK(scene::edit_distance("", "abc") == 3);
}

TEST_CASE("overrides (run --set KEY=VALUE) replace or add keys and are checked like the file") {
  const std::string text = "[mesh]\nsource = \"box\"\n[mesh.box]\ncells = [4, 4, 4]\n";
  const scene::Scene s =
      scene::parse_scene(text, "o.toml",
                         {"mesh.box.cells=[6, 7, 8]", "flow.scheme=central4", "time.end = 2.5",
                          "mesh.box.periodic=['x']", "run.overwrite=true"});
  CHECK(s.get<std::array<int, 3>>("mesh.box.cells") == std::array{6, 7, 8});
  CHECK(s.get<std::string>("flow.scheme") == "central4");  // a bare word is a string
  CHECK(s.get<double>("time.end") == 2.5);
  CHECK(s.get<std::vector<std::string>>("mesh.box.periodic") == std::vector<std::string>{"x"});
  CHECK(s.get<bool>("run.overwrite"));
  CHECK(s.is_set("time.end"));
  CHECK(s.location("time.end").file == "--set time.end = 2.5");
  CHECK(s.location("mesh.box.cells").file == "--set mesh.box.cells=[6, 7, 8]");

  auto error_with = [&](const std::string& setting) {
    try {
      scene::parse_scene(text, "o.toml", {setting});
    } catch (const scene::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A value the schema refuses is reported at the override, with the key.
  const auto bad_value = error_with("time.end=-1");
  CHECK(bad_value.find("--set time.end=-1:1:") == 0);
  CHECK(bad_value.find("'time.end'") != std::string::npos);
  CHECK(error_with("time.ende=1").find("time.ende") != std::string::npos);
  CHECK(error_with("flow.scheme=central9").find("central9") != std::string::npos);
  CHECK(error_with("no_equals_sign").find("expected KEY=VALUE") != std::string::npos);
  CHECK(error_with("=3").find("expected KEY=VALUE") != std::string::npos);
  CHECK(error_with("mesh..box=3").find("expected KEY=VALUE") != std::string::npos);
  CHECK(error_with("mesh.source.x=3").find("'mesh.source' is a value") != std::string::npos);
  CHECK(error_with("time.end=").find("not TOML") != std::string::npos);
}

// The options whose scene value is a name are enums in the solver: every value the scene accepts
// parses to an enum that prints back as the same name, and the scene's default is the option
// struct's default.
template <class Enum, class Parse, class Print>
void check_round_trip(const scene::Scene& s, const std::string& key,
                      const std::vector<std::string>& names, Parse parse, Print print,
                      Enum default_value) {
  CAPTURE(key);
  CHECK(parse(s.get<std::string>(key)) == default_value);
  for (const auto& name : names) CHECK(print(parse(name)) == name);
  CHECK_THROWS_AS(parse("no_such_" + key), std::invalid_argument);
}

TEST_CASE("named options: scene names <-> enums") {
  const auto s = scene::parse_scene("[mesh]\nsource = \"box\"\n", "b.toml");
  auto print = [](auto value) { return to_string(value); };
  check_round_trip(s, "flow.scheme", flow::convection_scheme_names(), flow::parse_convection_kind,
                   print, flow::ProjectionOptions{}.scheme);
  check_round_trip(s, "initial.type", flow::initial_type_names(), flow::parse_initial_type, print,
                   flow::InitialCondition{}.type);
  check_round_trip(s, "partition.method", mesh::partition_method_names(),
                   mesh::parse_partition_method, print, mesh::PartitionOptions{}.method);
  check_round_trip(s, "mesh.box.cell_type", mesh::box_cell_type_names(), mesh::parse_box_cell_type,
                   print, mesh::BoxSpec{}.cell_type);
  for (const auto& name : structure::material_law_names())
    CHECK(to_string(structure::parse_material_law(name)) == name);
}
