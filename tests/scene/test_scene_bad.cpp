// Known-bad scenes (scenes/bad/*.toml): each gives one exact message naming the file, line,
// column, key and what is accepted. The TOML syntax error names the place the parser stopped.
#include <doctest/doctest.h>

#include <filesystem>

#include "scene/scene.hpp"

namespace fs = std::filesystem;
using namespace valsalva;

namespace {

std::string error_of(const fs::path& file) {
  try {
    scene::load_scene(file);
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "no error";
}

struct Bad {
  const char* file;
  const char* message;  // after "<path>:"
};

// clang-format off
const Bad bad_scenes[] = {
  {"unknown_key.toml", "6:1: key 'mesh.box.cels': unknown key; did you mean 'mesh.box.cells'? (accepted: keys origin, length, cells, cell_type, perturbation, seed, periodic)"},
  {"unknown_section.toml", "5:2: key 'partiton': unknown table; did you mean 'partition'? (accepted: sections run, mesh, partition, flow, time, poisson, initial, output, forcing, boundary, les, probe, probes, sample, statistics, wall_shear, pressure_drop, section, sections, immersed, structure, valve)"},
  {"wrong_type.toml", "6:9: key 'mesh.box.cells': expected an array of 3 integers, got the string \"8 8 8\" (accepted: 3 values, each >= 1)"},
  {"out_of_range.toml", "6:16: key 'partition.ghost_layers': value 7 is out of range (accepted: [1, 4])"},
  {"unknown_enum.toml", "3:10: key 'mesh.source': unknown value \"boks\"; did you mean \"box\"? (accepted: \"box\", \"gmsh\", \"pipe\", \"cylinder_channel\", \"periodic_pipe\", \"extruded_pipe\")"},
  {"missing_required.toml", "5:2: key 'mesh.source': required key is missing; expected a string (accepted: \"box\", \"gmsh\", \"pipe\", \"cylinder_channel\", \"periodic_pipe\", \"extruded_pipe\")"},
  {"float_for_int.toml", "6:13: key 'run.log_every': expected an integer, got the float 2.5 (accepted: >= 1)"},
  {"negative_length.toml", "6:16: key 'mesh.box.length': element 2 is -1, out of range (accepted: 3 values, each > 0)"},
  {"wrong_size.toml", "6:10: key 'mesh.box.origin': expected an array of 3 numbers, got 2 values (accepted: 3 values)"},
  {"inactive_key.toml", "6:1: key 'mesh.pipe.radius': has no effect because mesh.source = \"box\" (accepted: only when mesh.source is \"pipe\")"},
  {"missing_pipe_size.toml", "5:7: key 'mesh.pipe.size': required key is missing; expected a number in m (accepted: > 0)"},
  {"bad_periodic_direction.toml", "6:18: key 'mesh.box.periodic': element 2: unknown value \"w\" (accepted: each of \"x\", \"y\", \"z\", no repeats)"},
  {"periodic_pair_incomplete.toml", "6:16: key 'mesh.periodic.inlet_outlet.slave': required key is missing; expected a string (accepted: any string)"},
  {"misplaced_key.toml", "4:1: key 'mesh.ghost_layers': unknown key; did you mean 'partition.ghost_layers'? (accepted: keys source, file, scale, box, pipe, extruded_pipe, periodic_pipe, cylinder_channel, periodic)"},
  {"perturbation_too_large.toml", "7:16: key 'mesh.box.perturbation': value 0.5 is out of range (accepted: [0, 0.4])"},
  {"gmsh_without_file.toml", "2:2: key 'mesh.file': required key is missing; expected a string (accepted: any string)"},
  {"bool_as_string.toml", "6:13: key 'run.overwrite': expected true or false, got the string \"yes\" (accepted: true, false)"},
  {"statistics_plane_without_normal.toml", "8:13: key 'statistics.mid.normal': required key is missing; expected an array of 3 numbers (accepted: 3 values)"},
  {"unknown_time_scheme.toml", "6:10: key 'time.scheme': unknown value \"rk4_clasic\"; did you mean \"rk4_classic\"? (accepted: \"rk4_jameson\", \"rk4_classic\")"},
  {"section_as_value.toml", "2:13: key 'partition': expected a table, got the integer 2 (accepted: keys ghost_layers, ghost_distance, method)"},
};
// clang-format on

const fs::path bad_dir = fs::path(VALSALVA_SOURCE_DIR) / "scenes/bad";

}  // namespace

TEST_CASE("every known-bad scene gives its exact message") {
  for (const auto& bad : bad_scenes) {
    CAPTURE(std::string(bad.file));
    const fs::path file = bad_dir / bad.file;
    REQUIRE(fs::exists(file));
    CHECK(error_of(file) == file.string() + ":" + bad.message);
  }
}

TEST_CASE("every file in scenes/bad is covered by a test") {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(bad_dir)) {
    const auto name = entry.path().filename().string();
    CAPTURE(name);
    bool listed = name == "syntax_error.toml" || name == "multiple_errors.toml";
    for (const auto& bad : bad_scenes) listed = listed || name == bad.file;
    CHECK(listed);
    CHECK(error_of(entry.path()) != "no error");
    ++count;
  }
  CHECK(count == std::size(bad_scenes) + 2);
}

TEST_CASE("a TOML syntax error names the file, line and column where parsing stopped") {
  const fs::path file = bad_dir / "syntax_error.toml";
  const std::string message = error_of(file);
  CHECK(message.rfind(file.string() + ":6:1: TOML syntax error: ", 0) == 0);
}

TEST_CASE("all problems of a scene are reported at once, in file order") {
  const fs::path file = bad_dir / "multiple_errors.toml";
  try {
    scene::load_scene(file);
    FAIL("multiple_errors.toml loaded");
  } catch (const scene::SceneError& e) {
    const std::string f = file.string();
    REQUIRE(e.problems().size() == 3);
    CHECK(e.problems()[0] == f + ":6:13: key 'mesh.box.cells': element 2 is 0, out of range "
                                 "(accepted: 3 values, each >= 1)");
    CHECK(e.problems()[1] ==
          f + ":7:8: key 'mesh.box.seed': value -1 is out of range (accepted: >= 0)");
    CHECK(e.problems()[2] ==
          f + ":10:1: key 'run.log_evry': unknown key; did you mean 'run.log_every'? (accepted: "
              "keys output_dir, overwrite, log_every, progress)");
    CHECK(std::string(e.what()) ==
          e.problems()[0] + "\n" + e.problems()[1] + "\n" + e.problems()[2]);
  }
}

TEST_CASE("a missing scene file is a scene::SceneError naming it") {
  const fs::path file = bad_dir / "does_not_exist.toml";
  CHECK(error_of(file) == file.string() + ": cannot open the scene file");
}
