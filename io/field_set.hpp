// Named nodal fields handed to a writer (run::RunLoop, the LES and immersed-structure outputs
// fill it; io::FieldOutput writes it).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "flow/operators.hpp"

namespace valsalva::io {

// Writes named nodal fields (local arrays, owned values read) as `basename` at `time`.
struct FieldSet {
  std::vector<std::pair<std::string, const flow::ScalarField*>> scalars;
  std::vector<std::pair<std::string, const flow::VectorField*>> vectors;
  const flow::VectorField* state_velocity =
      nullptr;  // the written state's velocity (derived fields)
};
using FieldSink = std::function<void(const std::string& basename, double time, const FieldSet&)>;

}  // namespace valsalva::io
