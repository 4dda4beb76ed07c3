// What a command is doing, for the one error that names nothing: std::bad_alloc. A Phase names
// the step for its lifetime and hands back the previous name when it ends normally; when an
// exception leaves it the name stays, so that the top-level handler can say what was being done
// when memory ran out.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace valsalva::run {

class Phase {
 public:
  explicit Phase(std::string what);
  ~Phase();
  void next(std::string what);  // the same scope moves on to its next step
  Phase(const Phase&) = delete;
  Phase& operator=(const Phase&) = delete;
  // The innermost phase, "" outside every phase.
  static const std::string& current();

 private:
  std::string previous_;
  int uncaught_;
};

// "reading the mesh mesh.file = 'root.msh'" or "generating the mesh mesh.source = box".
std::string mesh_phase(const scene::Scene& scene);

}  // namespace valsalva::run
