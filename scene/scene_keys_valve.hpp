// [valve]: the indices of a heart valve made of one immersed structure with three leaflets
// (valve/valve_monitor.hpp): declared in the scene schema, read into plain options.
#pragma once

#include <optional>

#include "analysis/valve_monitor_options.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"
#include "scene/scene_schema.hpp"

namespace valsalva::scene {

void declare_valve_keys(Schema& schema);
// Empty when valve.structure is empty. Throws SceneError naming the key for an unknown
// structure or patch, a zero axis, a non-positive annulus radius or TPG radius.
std::optional<analysis::ValveMonitorOptions> read_valve_monitor_options(const Scene& scene,
                                                                        const mesh::Mesh& mesh);

}  // namespace valsalva::scene
