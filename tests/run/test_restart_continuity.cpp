// A restart in place cuts every appended series back to the checkpoint: the section fluxes
// (sections.csv, by time) and the valve indices (valve.csv, by step) as the others; a series the
// table does not know is refused rather than continued uncut. Runs at 1 rank.
#include <doctest/doctest.h>
#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/comm.hpp"
#include "run/restart_continuity.hpp"

namespace fs = std::filesystem;
using namespace valsalva;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// An empty scratch folder of this process under the system's temporary folder.
fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("continue_in_place cuts sections.csv by time and valve.csv by step") {
  const fs::path dir = scratch_dir("valsalva_restart_continuity");
  const core::Comm comm(MPI_COMM_WORLD);
  const scene::Scene scene = scene::parse_scene("[mesh]\nsource = \"box\"\n", "cube.toml");
  // Steps 0..4 at dt = 0.1 written by the interrupted run; the checkpoint is at step 2, t = 0.2
  // (printed as 0.20000000000000001: the half-step margin keeps it).
  std::ofstream(dir / "sections.csv")
      << "time,mid_flux\n0,1\n0.1,2\n0.20000000000000001,3\n0.30000000000000004,4\n0.4,5\n";
  std::ofstream(dir / "valve.csv")
      << "step,time,cycle\n0,0,0\n1,0.1,0\n2,0.2,0\n3,0.3,0\n4,0.4,0\n";
  std::ofstream(dir / "valve_cycles.csv") << "cycle,start\n0,0\n";
  run::continue_in_place(dir, scene, 2, 0.2, 0.1, {"sections.csv", "valve.csv"}, comm);
  CHECK(read(dir / "sections.csv") == "time,mid_flux\n0,1\n0.1,2\n0.20000000000000001,3\n");
  CHECK(read(dir / "valve.csv") == "step,time,cycle\n0,0,0\n1,0.1,0\n2,0.2,0\n");
  // Not in the list: untouched (the valve monitor cuts valve_cycles.csv itself).
  CHECK(read(dir / "valve_cycles.csv") == "cycle,start\n0,0\n");
  CHECK(fs::exists(dir / "resolved_scene_restart_000000002.toml"));

  // An unknown name would be continued uncut: refused, naming it.
  CHECK_THROWS_WITH(run::continue_in_place(dir, scene, 2, 0.2, 0.1, {"valve_cycles.csv"}, comm),
                    doctest::Contains("'valve_cycles.csv' is not among the appended series"));
  fs::remove_all(dir);
}

TEST_CASE("restart_scene_change: keys added since the run was recorded are not a change") {
  const fs::path dir = scratch_dir("valsalva_restart_scene_change");
  const scene::Scene scene = scene::parse_scene("[mesh]\nsource = \"box\"\n", dir / "cube.toml");
  // The run as an older valsalva recorded it: the resolved scene without time.land_on.
  toml::table old_resolved = scene.table();
  old_resolved["time"].as_table()->erase("land_on");
  REQUIRE(!old_resolved["time"]["land_on"]);
  std::ofstream(dir / "resolved_scene.toml") << old_resolved;
  CHECK(run::restart_scene_change(dir / "resolved_scene.toml", scene).empty());

  // A real change is still named, with both values.
  const scene::Scene changed =
      scene::parse_scene("[mesh]\nsource = \"box\"\n[flow]\nviscosity = 0.5\n", dir / "cube.toml");
  const std::string message = run::restart_scene_change(dir / "resolved_scene.toml", changed);
  CHECK(message.find("flow.viscosity") != std::string::npos);
  CHECK(message.find("0.5 in") != std::string::npos);
  CHECK(run::restart_step_rule_change(dir / "resolved_scene.toml", changed).empty());
  fs::remove_all(dir);
}

TEST_CASE("restart_scene_change: the time-step rule may change, and the change is reported") {
  const fs::path dir = scratch_dir("valsalva_restart_step_rule");
  const scene::Scene scene =
      scene::parse_scene("[mesh]\nsource = \"box\"\n[time]\ncfl = 0.1\n", dir / "cube.toml");
  std::ofstream(dir / "resolved_scene.toml") << scene.table();
  CHECK(run::restart_step_rule_change(dir / "resolved_scene.toml", scene).empty());
  // A smaller step after a diverged stretch: allowed, and named with both values.
  const scene::Scene smaller = scene::parse_scene(
      "[mesh]\nsource = \"box\"\n[time]\ncfl = 0.05\nfourier = 0.1\n", dir / "cube.toml");
  CHECK(run::restart_scene_change(dir / "resolved_scene.toml", smaller).empty());
  const std::string rule = run::restart_step_rule_change(dir / "resolved_scene.toml", smaller);
  CHECK(rule.find("time.cfl 0.1 -> 0.05") != std::string::npos);
  CHECK(rule.find("time.fourier") != std::string::npos);
  // Other time keys still may not change.
  const scene::Scene scheme = scene::parse_scene(
      "[mesh]\nsource = \"box\"\n[time]\ncfl = 0.1\nscheme = \"rk4_classic\"\n", dir / "cube.toml");
  CHECK(run::restart_scene_change(dir / "resolved_scene.toml", scheme).find("time.scheme") !=
        std::string::npos);
  fs::remove_all(dir);
}
