#include "mesh/gmsh_reader.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <fstream>
#include <map>
#include <optional>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "mesh/msh_counts.hpp"

namespace valsalva::mesh {
namespace {

std::atomic<bool> session_open{false};

// Gmsh element type numbers (Gmsh reference manual, "MSH file format").
std::optional<mesh::CellType> cell_type_of(int gmsh_type) {
  switch (gmsh_type) {
    case 4:
      return mesh::CellType::tetra;
    case 5:
      return mesh::CellType::hexa;
    case 6:
      return mesh::CellType::prism;
    case 7:
      return mesh::CellType::pyramid;
    default:
      return std::nullopt;
  }
}

int face_node_count(int gmsh_type) {
  switch (gmsh_type) {
    case 2:
      return 3;  // 3-node triangle
    case 3:
      return 4;  // 4-node quadrangle
    default:
      return 0;
  }
}

std::string gmsh_type_name(int gmsh_type) {
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(gmsh_type, name, dim, order, nodes, local, primary);
  return fmt::format("'{}' (Gmsh type {}, {} nodes, order {})", name, gmsh_type, nodes, order);
}

// Maps Gmsh node tags (possibly sparse) to 0..n-1 in the order Gmsh returns them. Gmsh returns a
// tag defined twice twice: refused, else the later node would silently replace the earlier.
class NodeNumbering {
 public:
  NodeNumbering(const std::vector<std::size_t>& tags, const std::vector<double>& coords,
                const std::string& source) {
    const std::size_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
    dense_ = max_tag <= 4 * tags.size() + 1024;
    if (dense_) index_.assign(max_tag + 1, -1);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      if (const auto earlier = (*this)(tags[i]); earlier >= 0) {
        const auto at = [&](std::size_t k) {
          return fmt::format("({}, {}, {})", coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]);
        };
        throw MeshFileError(fmt::format("{}: node tag {} is defined twice, at {} and at {}", source,
                                        tags[i], at(std::size_t(earlier)), at(i)));
      }
      if (dense_)
        index_[tags[i]] = static_cast<mesh::GlobalIndex>(i);
      else
        sparse_[tags[i]] = static_cast<mesh::GlobalIndex>(i);
    }
  }
  mesh::GlobalIndex operator()(std::size_t tag) const {
    if (dense_) return tag < index_.size() ? index_[tag] : -1;
    auto it = sparse_.find(tag);
    return it == sparse_.end() ? -1 : it->second;
  }

 private:
  bool dense_ = true;
  std::vector<mesh::GlobalIndex> index_;
  std::unordered_map<std::size_t, mesh::GlobalIndex> sparse_;
};

// Compact node indices of element e (tag element_tag) of a Gmsh element block.
void element_nodes(const NodeNumbering& number, const std::vector<std::size_t>& node_tags,
                   std::size_t element_tag, std::size_t e, int n, const std::string& source,
                   std::vector<mesh::GlobalIndex>& nodes) {
  nodes.clear();
  for (int k = 0; k < n; ++k) {
    const std::size_t tag = node_tags[e * n + k];
    nodes.push_back(number(tag));
    if (nodes.back() < 0)
      throw MeshFileError(
          fmt::format("{}: element {} refers to undefined node {}", source, element_tag, tag));
  }
}

// Physical groups of dimension dim; an entity in two groups is an error.
struct EntityGroups {
  std::map<int, std::string> group_of;  // entity tag -> group name
  std::vector<std::string> names;       // group names in Gmsh's (tag) order
};

EntityGroups groups_of_entities(int dim, const std::string& source) {
  EntityGroups result;
  auto& group_of = result.group_of;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  for (const auto& [d, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(d, tag, name);
    if (name.empty()) name = fmt::format("{}_{}", dim == 3 ? "volume" : "surface", tag);
    result.names.push_back(name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
    for (int e : entities) {
      auto [it, inserted] = group_of.emplace(e, name);
      if (!inserted && it->second != name)
        throw MeshFileError(fmt::format(
            "{}: {} entity {} belongs to two physical groups, '{}' and '{}'; every {} must "
            "belong to one",
            source, dim == 3 ? "volume" : "surface", e, it->second, name,
            dim == 3 ? "cell" : "boundary face"));
    }
  }
  return result;
}

void add_cells(mesh::Mesh& mesh, const NodeNumbering& number, const std::string& source) {
  const auto groups = groups_of_entities(3, source);
  for (const auto& name : groups.names) mesh.add_region(name);
  const auto& regions = groups.group_of;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, 3);
  std::vector<mesh::GlobalIndex> nodes;
  for (const auto& [dim, entity] : entities) {
    auto group = regions.find(entity);
    // Volumes outside every physical group (files without groups) form the region "domain".
    const int region = mesh.add_region(group == regions.end() ? "domain" : group->second);
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, node_tags;
    gmsh::model::mesh::getElements(types, tags, node_tags, dim, entity);
    for (std::size_t t = 0; t < types.size(); ++t) {
      const auto type = cell_type_of(types[t]);
      if (!type && !tags[t].empty())
        throw MeshFileError(fmt::format(
            "{}: element {} is of unsupported type {}; only linear tetrahedra, hexahedra, "
            "prisms and pyramids are supported",
            source, tags[t].front(), gmsh_type_name(types[t])));
      const int n = mesh::node_count(*type);
      for (std::size_t e = 0; e < tags[t].size(); ++e) {
        element_nodes(number, node_tags[t], tags[t][e], e, n, source, nodes);
        mesh.add_cell(*type, nodes, region);
      }
    }
  }
}

void add_boundary_faces(mesh::Mesh& mesh, const NodeNumbering& number, const std::string& source) {
  // Surfaces outside every physical group (internal or untagged) are not boundary patches.
  std::vector<mesh::GlobalIndex> nodes;
  const auto groups = groups_of_entities(2, source);
  for (const auto& name : groups.names) mesh.add_patch(name);
  for (const auto& [entity, patch_name] : groups.group_of) {
    const int patch = mesh.add_patch(patch_name);
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, node_tags;
    gmsh::model::mesh::getElements(types, tags, node_tags, 2, entity);
    for (std::size_t t = 0; t < types.size(); ++t) {
      const int n = face_node_count(types[t]);
      if (n == 0 && !tags[t].empty())
        throw MeshFileError(fmt::format(
            "{}: element {} of physical surface '{}' is of unsupported type {}; only linear "
            "triangles and quadrangles are supported",
            source, tags[t].front(), patch_name, gmsh_type_name(types[t])));
      for (std::size_t e = 0; e < tags[t].size(); ++e) {
        element_nodes(number, node_tags[t], tags[t][e], e, n, source, nodes);
        mesh.add_face(nodes, patch);
      }
    }
  }
}

// A complete .msh file (ASCII or binary) ends with a "$End..." line; Gmsh itself accepts a file
// cut right after a complete section, so we look at the last line ourselves.
void check_complete(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshFileError(
        fmt::format("{}: cannot open the mesh file ({})", path.string(),
                    std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshFileError(fmt::format("{}: cannot open the mesh file", path.string()));
  in.seekg(0, std::ios::end);
  const std::streamoff size = std::max<std::streamoff>(in.tellg(), 0);
  const std::streamoff tail = std::min<std::streamoff>(size, 256);
  std::string text(static_cast<std::size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(text.data(), tail);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  const auto start = text.find_last_of('\n');
  const std::string last = text.substr(start == std::string::npos ? 0 : start + 1);
  if (size == 0 || last.rfind("$End", 0) != 0)
    throw MeshFileError(fmt::format(
        "{}: the file is truncated or not a Gmsh mesh: it does not end with a $End... section "
        "marker ({} bytes)",
        path.string(), size));
}

}  // namespace

GmshSession::GmshSession() {
  if (session_open.exchange(true))
    throw std::logic_error("GmshSession: Gmsh is already in use (sessions cannot nest)");
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
}

GmshSession::~GmshSession() {
  gmsh::finalize();
  session_open = false;
}

mesh::Mesh mesh_from_gmsh_model(const std::string& source) {
  return gmsh_call(source, [&] {
    mesh::Mesh mesh;
    mesh.source = source;
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric);
    mesh.nodes.reserve(tags.size());
    for (std::size_t i = 0; i < tags.size(); ++i)
      mesh.nodes.emplace_back(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);
    const NodeNumbering number(tags, coords, source);
    add_cells(mesh, number, source);
    if (mesh.num_cells() == 0)
      throw MeshFileError(fmt::format(
          "{}: no volume elements (the file holds no 3D mesh, or it is truncated)", source));
    add_boundary_faces(mesh, number, source);
    return mesh;
  });
}

mesh::Mesh read_gmsh(const std::filesystem::path& path) {
  const std::string source = path.string();
  check_complete(path);
  check_msh_counts(path);
  GmshSession session;
  gmsh_call(source +
                ": cannot read the file (a syntax error, a truncated section or an element "
                "type Gmsh does not know)",
            [&] { gmsh::open(source); });
  return mesh_from_gmsh_model(source);
}

void generate_deterministic_mesh(int dimension) {
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.RandomSeed", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::model::mesh::generate(dimension);
}

}  // namespace valsalva::mesh
