#include "valve/leaflet_groups.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace valsalva::valve {

std::vector<LeafletGroups> leaflet_groups(const structure::SolidMesh& mesh) {
  std::vector<LeafletGroups> out;
  for (int k = 1; mesh.node_sets.count(fmt::format("leaflet{}", k)); ++k) {
    const std::string name = fmt::format("leaflet{}", k);
    out.push_back({name, name + "_attachment", name + "_free_edge", name + "_aortic_face",
                   name + "_ventricular_face"});
  }
  if (out.empty())
    throw std::invalid_argument(fmt::format(
        "{}: no leaflets (no physical group 'leaflet1'; valsalva make-valve writes leaflets "
        "named leaflet1, leaflet2, leaflet3)",
        mesh.source));
  auto require_nodes = [&](const std::string& group) {
    auto it = mesh.node_sets.find(group);
    if (it == mesh.node_sets.end() || it->second.empty())
      throw std::invalid_argument(
          fmt::format("{}: physical group '{}' is missing or empty", mesh.source, group));
  };
  auto require_faces = [&](const std::string& group) {
    auto it = mesh.surface_sets.find(group);
    if (it == mesh.surface_sets.end() || it->second.empty())
      throw std::invalid_argument(fmt::format(
          "{}: physical surface '{}' is missing or has no element faces", mesh.source, group));
  };
  for (const auto& l : out) {
    require_nodes(l.name);
    require_nodes(l.attachment);
    require_nodes(l.free_edge);
    for (const auto* set : {&l.attachment, &l.free_edge, &l.aortic_face, &l.ventricular_face})
      require_faces(*set);
  }
  return out;
}

}  // namespace valsalva::valve
