#include "valve/leaflet_mesh.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "io/solid_gmsh_reader.hpp"
#include "mesh/gmsh_reader.hpp"
#include "structure/mesh_generators.hpp"
#include "valve/leaflet_groups.hpp"

namespace valsalva::valve {

using structure::FaceRef;
using structure::SolidMesh;
using structure::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kSets[] = {"attachment", "free_edge", "aortic_face", "ventricular_face"};

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Local nodes of Q2 hexahedron face f as a 9-node Gmsh quadrangle (corners counter-clockwise
// seen from outside, then edge mid-nodes, then the centre).
std::array<int, 9> quad9_of_face(int f) {
  const structure::HexFace face = structure::hex_face(f);
  int b = (face.axis + 1) % 3, c = (face.axis + 2) % 3;
  if (face.side < 0) std::swap(b, c);  // e_b x e_c along the outward normal
  static const int uv[9][2] = {{-1, -1}, {1, -1}, {1, 1},  {-1, 1}, {0, -1},
                               {1, 0},   {0, 1},  {-1, 0}, {0, 0}};
  std::array<int, 9> out{};
  for (int k = 0; k < 9; ++k) {
    Vec3 ref;
    ref[face.axis] = face.side;
    ref[b] = uv[k][0];
    ref[c] = uv[k][1];
    for (int a = 0; a < 27; ++a)
      if ((structure::hex_reference_node(structure::HexOrder::q2, a) - ref).norm() < 1e-12)
        out[k] = a;
  }
  return out;
}

}  // namespace

SolidMesh scalloped_leaflet(const LeafletPatch& p) {
  SolidMesh m = structure::structured_block(
      structure::HexOrder::q2, {p.n_angle, p.n_height, 1}, [&](const Vec3& s) {
        // q(u) = a u + (1 - a) sin(pi u / 2): q' = a at the posts (u = +-1), mean q' = 1.
        const double u = 2 * s[0] - 1, a = p.side_element_ratio;
        const double q = a * u + (1 - a) * std::sin(0.5 * kPi * u);
        const double th = p.centre_angle + 0.5 * q * p.span;
        const double za = p.z_base + (p.z_free - p.side_attachment - p.z_base) * q * q;
        const double r = p.radius + (s[2] - 0.5) * p.thickness;
        const double top = p.z_free + p.free_edge_rise * (1 - q * q);
        return Vec3(r * std::cos(th), r * std::sin(th), za + s[1] * (top - za));
      });
  m.source = fmt::format("<scalloped leaflet R={} t={} z={}..{} side={}>", p.radius, p.thickness,
                         p.z_base, p.z_free, p.side_attachment);
  std::vector<int> att = m.node_set("v0");
  std::vector<FaceRef> att_faces = m.surface_set("v0");
  for (const char* side : {"u0", "u1"}) {
    att.insert(att.end(), m.node_set(side).begin(), m.node_set(side).end());
    att_faces.insert(att_faces.end(), m.surface_set(side).begin(), m.surface_set(side).end());
  }
  sort_unique(att);
  m.node_sets["attachment"] = att;
  m.surface_sets["attachment"] = att_faces;
  structure::alias_sets(m, "v1", "free_edge");
  structure::alias_sets(m, "w0", "ventricular_face");
  structure::alias_sets(m, "w1", "aortic_face");
  return m;
}

std::array<int, 2> leaflet_elements(const ValveGeometry& g) {
  const double edge = 1.5 * g.mesh_size;
  const int n_angle = std::max(2, int(std::lround(g.leaflet_radius * g.leaflet_span() / edge)));
  const int n_height = std::max(1, int(std::lround(g.leaflet_height / edge)));
  return {n_angle, n_height};
}

SolidMesh valve_leaflets(const ValveGeometry& g) {
  const auto [n_angle, n_height] = leaflet_elements(g);
  SolidMesh all;
  all.order = structure::HexOrder::q2;
  all.source = "<valve leaflets>";
  std::vector<Vec3> nodes;
  for (int i = 1; i <= 3; ++i) {
    LeafletPatch p;
    p.radius = g.leaflet_radius;
    p.thickness = g.leaflet_thickness;
    p.span = g.leaflet_span();
    p.centre_angle = g.leaflet_centre_angle(i - 1);
    p.z_base = g.ring_height;
    p.z_free = g.free_edge_z();
    p.side_attachment = g.commissure_attachment;
    p.free_edge_rise = g.free_edge_rise;
    p.side_element_ratio = g.leaflet_side_element_ratio;
    p.n_angle = n_angle;
    p.n_height = n_height;
    const SolidMesh m = scalloped_leaflet(p);
    const int node0 = static_cast<int>(nodes.size()), elem0 = all.num_elements();
    for (int n = 0; n < m.num_nodes(); ++n) nodes.push_back(m.X.col(n));
    for (int c : m.connectivity) all.connectivity.push_back(c + node0);
    auto& mine = all.node_sets[fmt::format("leaflet{}", i)];
    for (int n = 0; n < m.num_nodes(); ++n) mine.push_back(n + node0);
    for (const char* set : kSets) {
      auto& ns = all.node_sets[fmt::format("leaflet{}_{}", i, set)];
      auto& un = all.node_sets[set];
      for (int n : m.node_set(set)) {
        ns.push_back(n + node0);
        un.push_back(n + node0);
      }
      auto& fs = all.surface_sets[fmt::format("leaflet{}_{}", i, set)];
      auto& uf = all.surface_sets[set];
      for (const FaceRef& f : m.surface_set(set)) {
        fs.push_back({f.element + elem0, f.face});
        uf.push_back({f.element + elem0, f.face});
      }
    }
  }
  all.X.resize(3, static_cast<long>(nodes.size()));
  for (std::size_t n = 0; n < nodes.size(); ++n) all.X.col(static_cast<long>(n)) = nodes[n];
  all.validate();
  return all;
}

void write_leaflets_gmsh(const std::filesystem::path& file, const SolidMesh& mesh) {
  const std::string source = file.string();
  mesh::GmshSession session;
  mesh::gmsh_call(source, [&] {
    gmsh::model::add("leaflets");
    const int nen = mesh.nodes_per_element();
    std::size_t element_tag = 1;
    int surface_tag = 1;
    std::map<std::string, std::vector<int>> unions;
    for (int i = 1; i <= 3; ++i) {
      const std::vector<int>& own = mesh.node_set(fmt::format("leaflet{}", i));
      std::vector<char> in(mesh.num_nodes(), 0);
      for (int n : own) in[n] = 1;
      gmsh::model::addDiscreteEntity(3, i);
      std::vector<std::size_t> tags;
      std::vector<double> xyz;
      for (int n : own) {
        tags.push_back(std::size_t(n) + 1);
        for (int k = 0; k < 3; ++k) xyz.push_back(mesh.X(k, n));
      }
      gmsh::model::mesh::addNodes(3, i, tags, xyz);
      std::vector<std::size_t> etags, enodes;
      for (int e = 0; e < mesh.num_elements(); ++e) {
        if (!in[mesh.element_nodes(e)[0]]) continue;
        etags.push_back(element_tag++);
        for (int a = 0; a < nen; ++a) enodes.push_back(std::size_t(mesh.element_nodes(e)[a]) + 1);
      }
      gmsh::model::mesh::addElementsByType(i, 12, etags, enodes);
      gmsh::model::addPhysicalGroup(3, {i}, i);
      gmsh::model::setPhysicalName(3, i, fmt::format("leaflet{}", i));
      for (const char* set : kSets) {
        const int s = surface_tag++;
        gmsh::model::addDiscreteEntity(2, s);
        std::vector<std::size_t> qtags, qnodes;
        for (const FaceRef& f : mesh.surface_set(fmt::format("leaflet{}_{}", i, set))) {
          qtags.push_back(element_tag++);
          for (int a : quad9_of_face(f.face))
            qnodes.push_back(std::size_t(mesh.element_nodes(f.element)[a]) + 1);
        }
        gmsh::model::mesh::addElementsByType(s, 10, qtags, qnodes);
        gmsh::model::addPhysicalGroup(2, {s}, s);
        gmsh::model::setPhysicalName(2, s, fmt::format("leaflet{}_{}", i, set));
        unions[set].push_back(s);
      }
    }
    int group = surface_tag;
    for (const char* set : kSets) {
      gmsh::model::addPhysicalGroup(2, unions[set], group);
      gmsh::model::setPhysicalName(2, group++, set);
    }
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write(source);
  });
}

SolidMesh read_valve_leaflets(const std::filesystem::path& file) {
  SolidMesh m = io::read_solid_gmsh(file);
  if (m.order != structure::HexOrder::q2)
    throw mesh::MeshFileError(
        fmt::format("{}: valve leaflet meshes must be 27-node (Q2) hexahedra", file.string()));
  const char* need =
      " (valve leaflet meshes need leaflet<i>, leaflet<i>_{attachment, free_edge, aortic_face, "
      "ventricular_face} for i = 1, 2, 3 and the unions; see docs/valve.md)";
  std::size_t leaflets = 0;
  try {
    leaflets = leaflet_groups(m).size();  // the per-leaflet groups, one check for both readers
  } catch (const std::invalid_argument& e) {
    throw mesh::MeshFileError(e.what() + std::string(need));
  }
  if (leaflets != 3)
    throw mesh::MeshFileError(
        fmt::format("{}: {} leaflets, not 3{}", file.string(), leaflets, need));
  for (const char* set : kSets)
    if (!m.surface_sets.count(set) || m.surface_sets.at(set).empty())
      throw mesh::MeshFileError(
          fmt::format("{}: physical group '{}' is missing or empty{}", file.string(), set, need));
  return m;
}

SolidMesh leaflet_submesh(const SolidMesh& all, int i, const Eigen::Matrix3Xd* positions,
                          Eigen::Matrix3Xd* out) {
  const std::string prefix = fmt::format("leaflet{}", i);
  const std::vector<int>& own = all.node_set(prefix);
  std::unordered_map<int, int> node_of;
  for (int n : own) node_of.emplace(n, static_cast<int>(node_of.size()));
  SolidMesh m;
  m.order = all.order;
  m.source = fmt::format("{} ({})", all.source, prefix);
  m.X.resize(3, static_cast<long>(own.size()));
  if (out) out->resize(3, static_cast<long>(own.size()));
  for (const auto& [old, now] : node_of) {
    m.X.col(now) = all.X.col(old);
    if (positions && out) out->col(now) = positions->col(old);
  }
  std::vector<int> element_of(all.num_elements(), -1);
  const int nen = all.nodes_per_element();
  for (int e = 0; e < all.num_elements(); ++e) {
    if (!node_of.count(all.element_nodes(e)[0])) continue;
    element_of[e] = m.num_elements();
    for (int a = 0; a < nen; ++a) m.connectivity.push_back(node_of.at(all.element_nodes(e)[a]));
  }
  for (const char* set : kSets) {
    const std::string name = prefix + "_" + set;
    if (auto it = all.node_sets.find(name); it != all.node_sets.end()) {
      auto& ns = m.node_sets[set];
      for (int n : it->second) ns.push_back(node_of.at(n));
      std::sort(ns.begin(), ns.end());
    }
    if (auto it = all.surface_sets.find(name); it != all.surface_sets.end())
      for (const FaceRef& f : it->second)
        m.surface_sets[set].push_back({element_of[f.element], f.face});
  }
  return m;
}

}  // namespace valsalva::valve
