#include "mesh/dual_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "core/compensated_sum.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/periodic.hpp"

namespace valsalva::mesh {

namespace {

using Vec = Eigen::Vector3d;

// Signed volume of the tetrahedron with base triangle (p0, p1, p2), oriented outward from the
// apex c: positive for a correctly oriented cell.
double tet_volume(const Vec& p0, const Vec& p1, const Vec& p2, const Vec& c) {
  return (p1 - p0).cross(p2 - p0).dot(p0 - c) / 6.0;
}

// Adds the tetrahedron (v0..v3) to the zeroth, first and second moments about `origin`
// (exact for a tetrahedron: int y y^T = V/20 (sum y_i y_i^T + (sum y_i)(sum y_i)^T)).
void add_tet_moments(const Vec& v0, const Vec& v1, const Vec& v2, const Vec& v3, double volume,
                     const Vec& origin, Vec& first, SymTensor& second) {
  const Vec y0 = v0 - origin, y1 = v1 - origin, y2 = v2 - origin, y3 = v3 - origin;
  const Vec s = y0 + y1 + y2 + y3;
  first += volume * s / 4.0;
  Eigen::Matrix3d m = y0 * y0.transpose() + y1 * y1.transpose() + y2 * y2.transpose() +
                      y3 * y3.transpose() + s * s.transpose();
  m *= volume / 20.0;
  second[0] += m(0, 0);
  second[1] += m(1, 1);
  second[2] += m(2, 2);
  second[3] += m(0, 1);
  second[4] += m(0, 2);
  second[5] += m(1, 2);
}

struct FaceKey {
  std::array<GlobalIndex, 4> n{-1, -1, -1, -1};
  bool operator==(const FaceKey&) const = default;
};
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::size_t h = 1469598103934665603ull;
    for (GlobalIndex v : k.n) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
    return h;
  }
};
template <class Range>
FaceKey face_key(const Range& nodes) {
  FaceKey k;
  std::size_t i = 0;
  for (GlobalIndex v : nodes) k.n[i++] = v;
  // Insertion sort of at most 4 entries (std::sort trips GCC 12's -Warray-bounds here).
  for (std::size_t a = 1; a < 4; ++a)
    for (std::size_t b = a; b > 0 && k.n[b] >= 0 && (k.n[b - 1] > k.n[b]); --b)
      std::swap(k.n[b - 1], k.n[b]);
  return k;
}

Vec centroid(const Mesh& mesh, std::span<const GlobalIndex> nodes) {
  Vec c = Vec::Zero();
  for (GlobalIndex n : nodes) c += mesh.nodes[n];
  return c / static_cast<double>(nodes.size());
}

bool on_periodic_patch(const Mesh& mesh, int patch) {
  for (const auto& link : mesh.periodic)
    if (mesh.patch_names[patch] == link.master || mesh.patch_names[patch] == link.slave)
      return true;
  return false;
}

// Unique edges between dual nodes in CSR form (row j lists k > j, sorted): cache-friendly
// lookups instead of a hash map over all edges.
struct EdgeTable {
  std::vector<GlobalIndex> row_start;  // size n + 1
  std::vector<GlobalIndex> column;
  std::vector<std::array<GlobalIndex, 2>> pairs;
  GlobalIndex find(GlobalIndex a, GlobalIndex b) const {
    const GlobalIndex j = std::min(a, b), k = std::max(a, b);
    for (GlobalIndex e = row_start[j]; e < row_start[j + 1]; ++e)
      if (column[e] == k) return e;
    throw std::logic_error("dual metrics: edge missing from the edge table");
  }
};

EdgeTable build_edges(const Mesh& mesh, const std::vector<GlobalIndex>& dual, GlobalIndex n) {
  std::vector<GlobalIndex> count(n + 1, 0);
  auto for_each_edge = [&](auto&& visit) {
    for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
      const auto cell = mesh.cell(c);
      for (const auto& [p, q] : cell_edges(mesh.cell_types[c])) {
        const GlobalIndex a = dual[cell[p]], b = dual[cell[q]];
        visit(std::min(a, b), std::max(a, b));
      }
    }
  };
  for_each_edge([&](GlobalIndex j, GlobalIndex) { ++count[j + 1]; });
  for (GlobalIndex j = 0; j < n; ++j) count[j + 1] += count[j];
  std::vector<GlobalIndex> raw(count[n]);
  std::vector<GlobalIndex> fill(count.begin(), count.end() - 1);
  for_each_edge([&](GlobalIndex j, GlobalIndex k) { raw[fill[j]++] = k; });
  EdgeTable t;
  t.row_start.assign(n + 1, 0);
  for (GlobalIndex j = 0; j < n; ++j) {
    auto first = raw.begin() + count[j], last = raw.begin() + count[j + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    for (auto it = first; it != last; ++it) {
      t.column.push_back(*it);
      t.pairs.push_back({j, *it});
    }
    t.row_start[j + 1] = static_cast<GlobalIndex>(t.column.size());
  }
  return t;
}

// The tagged boundary faces, and which cell face each one is (found while the cells are
// visited, so that no map over all cell faces is needed).
class TaggedFaces {
 public:
  explicit TaggedFaces(const Mesh& mesh) : mesh_(mesh), owner_(mesh.num_faces()) {
    index_.reserve(static_cast<std::size_t>(mesh.num_faces()));
    for (GlobalIndex f = 0; f < mesh.num_faces(); ++f)
      if (!index_.try_emplace(face_key(mesh.face(f)), f).second)
        throw std::runtime_error(fmt::format("{}: boundary face {} with nodes ({}) is tagged twice",
                                             mesh.source, f, fmt::join(mesh.face(f), ", ")));
  }
  void visit(const std::vector<GlobalIndex>& face_nodes, GlobalIndex cell, int local_face) {
    auto it = index_.find(face_key(face_nodes));
    if (it == index_.end()) return;
    auto& o = owner_[it->second];
    ++o.hits;
    o.cell = cell;
    o.local_face = local_face;
  }
  struct Owner {
    GlobalIndex cell = -1;
    int local_face = -1;
    int hits = 0;
  };
  // Throws when a tagged face is not exactly one cell's boundary face.
  const Owner& owner(GlobalIndex f) const {
    const auto& o = owner_[f];
    if (o.hits != 1)
      throw std::runtime_error(fmt::format(
          "{}: boundary face {} of patch '{}' with nodes ({}) is {}", mesh_.source, f,
          mesh_.patch_names[mesh_.face_patches[f]], fmt::join(mesh_.face(f), ", "),
          o.hits == 0 ? "not a face of any cell" : "an interior face (shared by two cells)"));
    return o;
  }

 private:
  const Mesh& mesh_;
  std::unordered_map<FaceKey, GlobalIndex, FaceKeyHash> index_;
  std::vector<Owner> owner_;
};

// Boundary dual faces from the tagged boundary faces, oriented like the owning cell's face
// (outward).
void add_boundary_faces(const Mesh& mesh, const TaggedFaces& tagged, DualMetrics& m) {
  const int num_patches = static_cast<int>(mesh.patch_names.size());
  std::unordered_map<std::int64_t, std::size_t> slot;  // (dual node, patch) -> boundary index
  std::vector<GlobalIndex> fnodes;
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    const auto& owner = tagged.owner(f);
    const int patch = mesh.face_patches[f];
    if (on_periodic_patch(mesh, patch)) continue;
    const auto cell = mesh.cell(owner.cell);
    const auto& local = cell_faces(mesh.cell_types[owner.cell])[owner.local_face];
    fnodes.clear();
    for (int i : local) fnodes.push_back(cell[i]);
    const Vec cf = centroid(mesh, fnodes);
    const std::size_t nf = fnodes.size();
    for (std::size_t i = 0; i < nf; ++i) {
      const GlobalIndex a = fnodes[i], b = fnodes[(i + 1) % nf];
      const Vec mid = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
      const Vec area_a = 0.5 * (mid - mesh.nodes[a]).cross(cf - mesh.nodes[a]);
      const Vec area_b = 0.5 * (mesh.nodes[b] - mid).cross(cf - mid);
      for (auto [node, area] : {std::pair{a, area_a}, std::pair{b, area_b}}) {
        const GlobalIndex d = m.dual_of_mesh_node[node];
        auto [s, inserted] = slot.try_emplace(d * num_patches + patch, m.boundary.size());
        if (inserted) m.boundary.push_back({d, patch, Vec::Zero()});
        m.boundary[s->second].area += area;
      }
    }
  }
}

// A dual volume that does not close has a boundary face without a patch (or a broken cell):
// the closure identity is exact by construction otherwise.
void check_closure(const Mesh& mesh, const DualMetrics& m) {
  std::vector<Vec> sum(m.num_nodes(), Vec::Zero());
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    sum[m.edges[e][0]] += m.edge_normal[e];
    sum[m.edges[e][1]] -= m.edge_normal[e];
  }
  for (const auto& b : m.boundary) sum[b.node] += b.area;
  for (GlobalIndex j = 0; j < m.num_nodes(); ++j)
    if (sum[j].norm() > 1e-9 * m.h[j] * m.h[j]) {
      const Vec& x = m.position[j];
      throw std::runtime_error(fmt::format(
          "{}: the dual volume of node {} at ({:.6g}, {:.6g}, {:.6g}) is not closed: a boundary "
          "face there belongs to no boundary patch (missing physical group)",
          mesh.source, m.mesh_node_of_dual[j], x[0], x[1], x[2]));
    }
}

void finish_derived_metrics(DualMetrics& m) {
  const GlobalIndex n = m.num_nodes();
  m.h.resize(n);
  for (GlobalIndex j = 0; j < n; ++j) m.h[j] = std::cbrt(m.volume[j]);
  std::vector<Eigen::Matrix3d> sum(n, Eigen::Matrix3d::Zero());
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const Eigen::Matrix3d sd = m.edge_normal[e] * m.edge_vector[e].transpose();
    sum[m.edges[e][0]] += sd;
    sum[m.edges[e][1]] += sd;
  }
  m.gradient_correction.resize(n);
  for (GlobalIndex j = 0; j < n; ++j)
    m.gradient_correction[j] = (sum[j] / (2.0 * m.volume[j])).inverse();
}

}  // namespace

double mesh_volume(const Mesh& mesh) {
  core::CompensatedSum total;
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) total.add(cell_volume(mesh, c));
  return total.value();
}

DualMetrics compute_dual_metrics(const Mesh& mesh) {
  const PeriodicMap periodic = match_periodic_nodes(mesh);
  DualMetrics m;
  const GlobalIndex n_mesh = mesh.num_nodes();

  // Dual nodes: one per periodic representative, numbered in mesh order.
  m.dual_of_mesh_node.assign(n_mesh, -1);
  for (GlobalIndex i = 0; i < n_mesh; ++i)
    if (periodic.representative[i] == i) {
      m.dual_of_mesh_node[i] = static_cast<GlobalIndex>(m.mesh_node_of_dual.size());
      m.mesh_node_of_dual.push_back(i);
    }
  for (GlobalIndex i = 0; i < n_mesh; ++i)
    m.dual_of_mesh_node[i] = m.dual_of_mesh_node[periodic.representative[i]];
  const GlobalIndex n = static_cast<GlobalIndex>(m.mesh_node_of_dual.size());
  m.position.resize(n);
  for (GlobalIndex d = 0; d < n; ++d) m.position[d] = mesh.nodes[m.mesh_node_of_dual[d]];

  m.volume.assign(n, 0.0);
  m.first_moment.assign(n, Vec::Zero());
  m.second_moment.assign(n, SymTensor{});

  const EdgeTable edge_table = build_edges(mesh, m.dual_of_mesh_node, n);
  m.edges = edge_table.pairs;
  m.edge_normal.assign(m.edges.size(), Vec::Zero());
  m.edge_vector.assign(m.edges.size(), Vec::Zero());
  TaggedFaces tagged(mesh);

  std::vector<GlobalIndex> fnodes;
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto cell = mesh.cell(c);
    const Vec cc = centroid(mesh, cell);
    const auto faces = cell_faces(mesh.cell_types[c]);
    for (int lf = 0; lf < static_cast<int>(faces.size()); ++lf) {
      const auto& f = faces[lf];
      fnodes.clear();
      for (int i : f) fnodes.push_back(cell[i]);
      tagged.visit(fnodes, c, lf);
      const Vec cf = centroid(mesh, fnodes);
      const std::size_t nf = fnodes.size();
      for (std::size_t i = 0; i < nf; ++i) {
        const GlobalIndex a = fnodes[i], b = fnodes[(i + 1) % nf];
        const Vec& xa = mesh.nodes[a];
        const Vec& xb = mesh.nodes[b];
        const Vec mid = 0.5 * (xa + xb);
        const GlobalIndex da = m.dual_of_mesh_node[a], db = m.dual_of_mesh_node[b];
        const double va = tet_volume(xa, mid, cf, cc);
        const double vb = tet_volume(mid, xb, cf, cc);
        m.volume[da] += va;
        m.volume[db] += vb;
        add_tet_moments(xa, mid, cf, cc, va, xa, m.first_moment[da], m.second_moment[da]);
        add_tet_moments(mid, xb, cf, cc, vb, xb, m.first_moment[db], m.second_moment[db]);
        // Dual-face piece (mid, cf, cc) between a and b, area vector oriented a -> b.
        const Vec s_ab = 0.5 * (cc - mid).cross(cf - mid);
        const GlobalIndex e = edge_table.find(da, db);
        const bool forward = da < db;
        m.edge_normal[e] += forward ? s_ab : Vec(-s_ab);
        // Edge vector x_k - x_j between the images of the two dual nodes inside this cell;
        // a periodic direction with fewer than 3 cells would make it ambiguous.
        const Vec d = forward ? Vec(xb - xa) : Vec(xa - xb);
        if (m.edge_vector[e].isZero(0.0)) {
          m.edge_vector[e] = d;
        } else if ((m.edge_vector[e] - d).norm() > 1e-9 * d.norm()) {
          throw std::runtime_error(fmt::format(
              "{}: nodes {} and {} are joined both directly and across a periodic boundary; "
              "a periodic direction needs at least 3 cells",
              mesh.source, a, b));
        }
      }
    }
  }

  add_boundary_faces(mesh, tagged, m);
  finish_derived_metrics(m);
  check_closure(mesh, m);
  return m;
}

}  // namespace valsalva::mesh
