#include "run/phase.hpp"

#include <fmt/format.h>

#include <exception>
#include <utility>

namespace valsalva::run {

namespace {
std::string current_phase;  // one command per process, one thread
}

Phase::Phase(std::string what)
    : previous_(std::exchange(current_phase, std::move(what))),
      uncaught_(std::uncaught_exceptions()) {}

Phase::~Phase() {
  if (std::uncaught_exceptions() > uncaught_) return;  // unwinding: keep the failing phase
  current_phase = std::move(previous_);
}

void Phase::next(std::string what) {
  current_phase = std::move(what);
}

const std::string& Phase::current() {
  return current_phase;
}

std::string mesh_phase(const scene::Scene& scene) {
  const auto source = scene.get<std::string>("mesh.source");
  if (source == "gmsh")
    return fmt::format("reading the mesh mesh.file = '{}'", scene.path("mesh.file").string());
  return fmt::format("generating the mesh mesh.source = {}", source);
}

}  // namespace valsalva::run
