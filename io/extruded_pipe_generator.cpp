// Extruded inlet/outlet pipe mesh; see extruded_pipe_generator.hpp.
#include "io/extruded_pipe_generator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/prism_split.hpp"

namespace valsalva::io {

flow::Mesh generate_extruded_pipe_mesh(const ExtrudedPipeSpec& s) {
  for (const auto& [name, value] :
       {std::pair{"radius", s.radius}, {"length", s.length}, {"target_size", s.target_size}})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format(
          "generate_extruded_pipe_mesh: {} must be positive and finite, got {}", name, value));
  if (!(s.layer_height >= 0) || !std::isfinite(s.layer_height))
    throw std::invalid_argument(fmt::format(
        "generate_extruded_pipe_mesh: layer_height must be >= 0 and finite, got {}",
        s.layer_height));
  const double dz = s.layer_height > 0 ? s.layer_height : s.target_size;
  const int layers = std::max(1, static_cast<int>(std::lround(s.length / dz)));
  const std::string source = fmt::format(
      "extruded_pipe(radius={:g}, length={:g}, size={:g}, layers={}, wall={:g}/{:g}, "
      "rows={:g}*{:g}^k<={:g})",
      s.radius, s.length, s.target_size, layers, s.grading.wall_size, s.grading.wall_distance,
      s.grading.layer_first, s.grading.layer_ratio, s.grading.layer_thickness);
  const Disk disk = triangulate_disk(s.radius, s.target_size, s.grading, source);
  std::vector<double> z;
  for (int l = 0; l <= layers; ++l) z.push_back(s.length * l / layers);
  return split_prisms_to_tetrahedra(extrude_disk(disk, z, "inlet", "outlet", source));
}

}  // namespace valsalva::io
