// docs/scenes.md is generated from the key declarations; this test fails when the committed
// file differs from what the declarations generate, and says how to regenerate it.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_docs.hpp"

namespace fs = std::filesystem;
using namespace valsalva;

TEST_CASE("docs/scenes.md matches the scene-key declarations byte for byte") {
  std::ostringstream generated;
  scene::write_scene_docs(generated);
  const fs::path committed = fs::path(VALSALVA_SOURCE_DIR) / "docs/scenes.md";
  std::ifstream in(committed, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const bool same = in.good() && text.str() == generated.str();
  if (!same) {
    // Leave the fresh version next to the test so it can be copied without the app.
    const fs::path fresh = fs::current_path() / "scenes.md.generated";
    std::ofstream(fresh, std::ios::binary) << generated.str();
    FAIL_CHECK(
        committed.string() << " is out of date with scene/scene_keys_*.cpp; regenerate it with\n"
                           << "  build/bin/valsalva docs-scenes > docs/scenes.md\n"
                           << "or copy " << fresh.string());
  }
  // Every declared key is documented.
  for (const auto& key : scene::scene_schema().keys()) {
    const auto leaf = scene::split_path(key.path).back();
    CAPTURE(key.path);
    CHECK(generated.str().find("| `" + leaf + "` |") != std::string::npos);
  }
  for (const auto& section : scene::scene_schema().sections())
    CHECK(generated.str().find("## `[" + section.path + "]`") != std::string::npos);
}

TEST_CASE("the docs show defaults, units, ranges and conditions") {
  std::ostringstream out;
  scene::write_scene_docs(out);
  const std::string md = out.str();
  CHECK(md.find("| `ghost_layers` | int | `2` | - | [1, 4] |") != std::string::npos);
  CHECK(md.find("| `length` | float[3] | `[1.0, 1.0, 1.0]` | m | 3 values, each > 0 |") !=
        std::string::npos);
  CHECK(md.find("| `source` | enum | required | - | \"box\", \"gmsh\", \"pipe\", "
                "\"cylinder_channel\", \"periodic_pipe\", \"extruded_pipe\" |") !=
        std::string::npos);
  CHECK(md.find("Used only when `mesh.source` is `\"pipe\"`.") != std::string::npos);
  CHECK(md.find("| `output_dir` | string | `\"runs/<scene file stem>\"` |") != std::string::npos);
}
