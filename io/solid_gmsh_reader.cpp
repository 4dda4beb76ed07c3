#include "io/solid_gmsh_reader.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <map>
#include <unordered_map>

#include "mesh/gmsh_reader.hpp"
#include "mesh/msh_counts.hpp"

namespace valsalva::io {

namespace {

using structure::HexOrder;
using Key = std::array<std::size_t, 4>;  // sorted corner node tags of a face

Key sorted(Key k) {
  std::sort(k.begin(), k.end());
  return k;
}

std::string group_name(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  return name.empty() ? fmt::format("physical{}_{}", dim, tag) : name;
}

}  // namespace

structure::SolidMesh solid_mesh_from_gmsh_model(const std::string& source) {
  return mesh::gmsh_call(source, [&] {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 3, -1);
    structure::SolidMesh mesh;
    mesh.source = source;
    int hex_type = 0;
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (tags[t].empty()) continue;
      if (types[t] != 5 && types[t] != 12) {
        std::string name;
        int dim = 0, order = 0, nn = 0, np = 0;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(types[t], name, dim, order, nn, local, np);
        throw mesh::MeshFileError(
            fmt::format("{}: element {} is a {} (Gmsh type {}); solid meshes take only 8-node or "
                        "27-node hexahedra",
                        source, tags[t].front(), name, types[t]));
      }
      if (hex_type && hex_type != types[t])
        throw mesh::MeshFileError(fmt::format("{}: mixes 8-node and 27-node hexahedra (element {})",
                                              source, tags[t].front()));
      hex_type = types[t];
    }
    if (!hex_type)
      throw mesh::MeshFileError(
          fmt::format("{}: no hexahedra (no 3D mesh, or it is not recombined)", source));
    mesh.order = hex_type == 5 ? HexOrder::q1 : HexOrder::q2;
    const int nen = mesh.nodes_per_element();

    // Nodes used by hexahedra, renumbered in tag order.
    std::vector<std::size_t> used;
    for (std::size_t t = 0; t < types.size(); ++t)
      used.insert(used.end(), nodes[t].begin(), nodes[t].end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::unordered_map<std::size_t, int> index;
    for (std::size_t i = 0; i < used.size(); ++i) index[used[i]] = static_cast<int>(i);
    mesh.X.resize(3, static_cast<long>(used.size()));
    std::vector<std::size_t> ntags;
    std::vector<double> coords, param;
    gmsh::model::mesh::getNodes(ntags, coords, param);
    for (std::size_t i = 0; i < ntags.size(); ++i)
      if (auto it = index.find(ntags[i]); it != index.end())
        mesh.X.col(it->second) =
            structure::Vec3(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);

    std::map<Key, structure::FaceRef> face_of;
    for (std::size_t t = 0; t < types.size(); ++t)
      for (std::size_t e = 0; e < tags[t].size(); ++e) {
        const int id = mesh.num_elements();
        const std::size_t* en = nodes[t].data() + e * nen;
        for (int a = 0; a < nen; ++a) mesh.connectivity.push_back(index.at(en[a]));
        for (int f = 0; f < 6; ++f) {
          const auto fn = structure::hex_face_nodes(HexOrder::q1, f);
          face_of[sorted({en[fn[0]], en[fn[1]], en[fn[2]], en[fn[3]]})] = {id, f};
        }
      }

    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, -1);
    for (const auto& [dim, tag] : groups) {
      const std::string name = group_name(dim, tag);
      std::vector<std::size_t> gn;
      std::vector<double> gc;
      gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, gn, gc);
      auto& set = mesh.node_sets[name];
      for (std::size_t n : gn)
        if (auto it = index.find(n); it != index.end()) set.push_back(it->second);
      std::sort(set.begin(), set.end());
      set.erase(std::unique(set.begin(), set.end()), set.end());
      if (dim != 2) continue;
      std::vector<int> ents;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, ents);
      for (int ent : ents) {
        std::vector<int> st;
        std::vector<std::vector<std::size_t>> stags, snodes;
        gmsh::model::mesh::getElements(st, stags, snodes, 2, ent);
        for (std::size_t t = 0; t < st.size(); ++t) {
          if (st[t] != 3 && st[t] != 10) continue;  // quadrangles (4 or 9 nodes)
          const std::size_t stride = st[t] == 3 ? 4 : 9;
          for (std::size_t q = 0; q < stags[t].size(); ++q) {
            const std::size_t* qn = snodes[t].data() + q * stride;
            auto it = face_of.find(sorted({qn[0], qn[1], qn[2], qn[3]}));
            if (it == face_of.end())
              throw mesh::MeshFileError(
                  fmt::format("{}: quadrangle {} of physical surface '{}' is not a face of any "
                              "hexahedron",
                              source, stags[t][q], name));
            mesh.surface_sets[name].push_back(it->second);
          }
        }
      }
    }
    mesh.validate();
    return mesh;
  });
}

structure::SolidMesh read_solid_gmsh(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw mesh::MeshFileError(fmt::format(
        "{}: not a readable mesh file (missing, a directory or a special file)", source));
  mesh::check_msh_counts(path);
  mesh::GmshSession session;
  mesh::gmsh_call(source + ": cannot read the file", [&] { gmsh::open(source); });
  return solid_mesh_from_gmsh_model(source);
}

}  // namespace valsalva::io
