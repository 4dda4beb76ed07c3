// Generates docs/scenes.md from the scene-key declarations, so the reference cannot drift from
// the code. `valsalva docs-scenes > docs/scenes.md` calls it; tests/io/test_scene_docs.cpp
// checks that the committed file is what it generates.
#pragma once

#include <ostream>

#include "scene/scene_schema.hpp"

namespace valsalva::scene {

void write_scene_docs(std::ostream& out, const Schema& schema = scene_schema());

}  // namespace valsalva::scene
