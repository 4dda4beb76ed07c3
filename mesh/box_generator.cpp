#include "mesh/box_generator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "core/enum_names.hpp"
#include "mesh/mesh_check.hpp"

namespace valsalva::mesh {

namespace {

using mesh::CellType;
using mesh::GlobalIndex;
using Vec = Eigen::Vector3d;

// Gmsh-ordered hexahedron corners as (i, j, k) offsets.
constexpr std::array<std::array<int, 3>, 8> kHexCorner{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

// Kuhn split: the 6 tetrahedra along the paths 0 -> 6 through the cube (gmsh corner numbers);
// every face gets the diagonal from its lowest to its highest corner, so neighbours conform.
constexpr std::array<std::array<int, 4>, 6> kKuhnTets{
    {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 3, 2, 6}, {0, 3, 7, 6}, {0, 4, 5, 6}, {0, 4, 7, 6}}};

// Prisms extruded along x; the (y, z) square is split by the same diagonal as Kuhn's x faces.
constexpr std::array<std::array<int, 6>, 2> kPrisms{{{0, 3, 7, 1, 2, 6}, {0, 7, 4, 1, 6, 5}}};

// Deterministic uniform number in [-1, 1] from a node's wrapped grid index (so that periodic
// images get the same perturbation).
double hashed_uniform(std::uint64_t seed, std::int64_t i, std::int64_t j, std::int64_t k, int c) {
  std::uint64_t h = seed * 0x9E3779B97F4A7C15ull;
  for (std::uint64_t v : {static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j),
                          static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(c)}) {
    h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
  }
  return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

class BoxBuilder {
 public:
  explicit BoxBuilder(const BoxSpec& spec) : spec_(spec) {
    mesh_.source = fmt::format("box {}x{}x{} {}", spec.cells[0], spec.cells[1], spec.cells[2],
                               to_string(spec.cell_type));
    mesh_.add_region("fluid");
    for (const char* p : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) mesh_.add_patch(p);
    make_grid_nodes();
  }

  mesh::Mesh build() {
    const auto [nx, ny, nz] = spec_.cells;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) add_hex_cell(i, j, k);
    add_boundary_faces();
    const char* axes[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d)
      if (spec_.periodic[d]) {
        Vec t = Vec::Zero();
        t[d] = spec_.length[d];
        mesh_.periodic.push_back({fmt::format("{}min", axes[d]), fmt::format("{}max", axes[d]), t});
      }
    return std::move(mesh_);
  }

 private:
  GlobalIndex grid_node(int i, int j, int k) const {
    return (static_cast<GlobalIndex>(k) * (spec_.cells[1] + 1) + j) * (spec_.cells[0] + 1) + i;
  }

  void make_grid_nodes() {
    const auto [nx, ny, nz] = spec_.cells;
    const Vec h = spec_.length.cwiseQuotient(Vec(nx, ny, nz));
    const std::array<int, 3> n{nx, ny, nz};
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
          const std::array<int, 3> ijk{i, j, k};
          Vec x = spec_.origin + Vec(i * h[0], j * h[1], k * h[2]);
          if (spec_.perturbation > 0) {
            std::array<int, 3> wrapped = ijk;
            for (int d = 0; d < 3; ++d)
              if (spec_.periodic[d]) wrapped[d] = ijk[d] % n[d];
            for (int c = 0; c < 3; ++c) {
              const bool on_wall = !spec_.periodic[c] && (ijk[c] == 0 || ijk[c] == n[c]);
              if (on_wall) continue;  // boundary nodes stay on their planes
              x[c] += spec_.perturbation * h[c] *
                      hashed_uniform(spec_.seed, wrapped[0], wrapped[1], wrapped[2], c);
            }
          }
          mesh_.nodes.push_back(x);
          logical_.push_back(ijk);
        }
  }

  BoxCellType type_of_cell(int i) const {
    if (spec_.cell_type != BoxCellType::mixed) return spec_.cell_type;
    // Slabs along x: hexahedra | pyramids | tetrahedra | prisms (conforming interfaces).
    const int q = spec_.cells[0] / 4;
    if (i < q) return BoxCellType::hexa;
    if (i < 2 * q) return BoxCellType::pyramid;
    if (i < 3 * q) return BoxCellType::tetra;
    return BoxCellType::prism;
  }

  void add_oriented(CellType type, std::vector<GlobalIndex> nodes) {
    mesh_.add_cell(type, nodes, 0);
    const GlobalIndex c = mesh_.num_cells() - 1;
    if (mesh::cell_volume(mesh_, c) >= 0) return;
    // Mirror the ordering: swap two base nodes (and their top partners for prisms).
    const auto first = mesh_.cell_nodes.begin() + mesh_.cell_offsets[c];
    if (type == CellType::tetra) std::swap(first[1], first[2]);
    if (type == CellType::prism) {
      std::swap(first[1], first[2]);
      std::swap(first[4], first[5]);
    }
    if (type == CellType::pyramid) std::swap(first[1], first[3]);
  }

  void add_hex_cell(int i, int j, int k) {
    std::array<GlobalIndex, 8> c;
    for (int v = 0; v < 8; ++v)
      c[v] = grid_node(i + kHexCorner[v][0], j + kHexCorner[v][1], k + kHexCorner[v][2]);
    switch (type_of_cell(i)) {
      case BoxCellType::hexa:
        mesh_.add_cell(CellType::hexa, c, 0);
        return;
      case BoxCellType::tetra:
        for (const auto& t : kKuhnTets)
          add_oriented(CellType::tetra, {c[t[0]], c[t[1]], c[t[2]], c[t[3]]});
        return;
      case BoxCellType::prism:
        for (const auto& p : kPrisms)
          add_oriented(CellType::prism, {c[p[0]], c[p[1]], c[p[2]], c[p[3]], c[p[4]], c[p[5]]});
        return;
      case BoxCellType::pyramid:
        add_pyramids(i, c);
        return;
      case BoxCellType::mixed:
        break;  // type_of_cell never returns it
    }
    throw std::logic_error("box mesh: no cell type for a mixed-mesh slab");
  }

  // Six pyramids around a centre node, one on each hexahedron face. In a mixed mesh the +x
  // pyramid next to the tetrahedra slab is split into two tetrahedra along Kuhn's diagonal.
  void add_pyramids(int i, const std::array<GlobalIndex, 8>& c) {
    Vec centre = Vec::Zero();
    for (GlobalIndex n : c) centre += mesh_.nodes[n];
    mesh_.nodes.push_back(centre / 8.0);
    logical_.push_back({-1, -1, -1});
    const GlobalIndex apex = mesh_.num_nodes() - 1;
    const bool next_is_tetra =
        spec_.cell_type == BoxCellType::mixed && type_of_cell(i + 1) == BoxCellType::tetra;
    for (const auto& f : mesh::cell_faces(CellType::hexa)) {
      const bool plus_x = f == std::vector<int>{1, 2, 6, 5};
      if (plus_x && next_is_tetra) {
        add_oriented(CellType::tetra, {c[1], c[2], c[6], apex});
        add_oriented(CellType::tetra, {c[1], c[6], c[5], apex});
        continue;
      }
      add_oriented(CellType::pyramid, {c[f[0]], c[f[3]], c[f[2]], c[f[1]], apex});
    }
  }

  void add_boundary_faces() {
    // Cell faces seen once are on the boundary; the patch follows from the grid indices.
    struct KeyHash {
      std::size_t operator()(const std::array<GlobalIndex, 4>& k) const {
        std::size_t h = 1469598103934665603ull;
        for (GlobalIndex v : k) h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
        return h;
      }
    };
    auto key_of = [](const std::vector<GlobalIndex>& nodes) {
      std::array<GlobalIndex, 4> k{-1, -1, -1, -1};
      std::copy(nodes.begin(), nodes.end(), k.begin());
      // Insertion sort of at most 4 entries (std::sort trips GCC 12's -Warray-bounds here).
      for (std::size_t a = 1; a < 4; ++a)
        for (std::size_t b = a; b > 0 && k[b] >= 0 && (k[b - 1] > k[b]); --b)
          std::swap(k[b - 1], k[b]);
      return k;
    };
    std::unordered_map<std::array<GlobalIndex, 4>, int, KeyHash> seen;
    std::vector<std::vector<GlobalIndex>> faces;
    for (GlobalIndex cidx = 0; cidx < mesh_.num_cells(); ++cidx) {
      const auto cell = mesh_.cell(cidx);
      for (const auto& f : mesh::cell_faces(mesh_.cell_types[cidx])) {
        std::vector<GlobalIndex> nodes;
        for (int v : f) nodes.push_back(cell[v]);
        auto [it, inserted] = seen.try_emplace(key_of(nodes), 0);
        ++it->second;
        if (inserted) faces.push_back(nodes);
      }
    }
    const std::array<int, 3> n = spec_.cells;
    for (const auto& nodes : faces) {
      if (seen[key_of(nodes)] != 1) continue;
      int patch = -1;
      for (int d = 0; d < 3 && patch < 0; ++d) {
        bool all_min = true, all_max = true;
        for (GlobalIndex v : nodes) {
          all_min = all_min && logical_[v][d] == 0;
          all_max = all_max && logical_[v][d] == n[d];
        }
        if (all_min) patch = 2 * d;
        if (all_max) patch = 2 * d + 1;
      }
      if (patch < 0) throw std::logic_error("box mesh: boundary face off the box faces");
      mesh_.add_face(nodes, patch);
    }
  }

  const BoxSpec& spec_;
  mesh::Mesh mesh_;
  std::vector<std::array<int, 3>> logical_;
};

}  // namespace

constexpr core::EnumNames<BoxCellType, 5> kCellTypes{{"hexa", "tetra", "prism", "pyramid", "mixed"},
                                                     "box mesh: cell_type"};

VALSALVA_ENUM_NAMES(BoxCellType, kCellTypes, box_cell_type_names, to_string, parse_box_cell_type)

mesh::Mesh generate_box(const BoxSpec& spec) {
  for (int d = 0; d < 3; ++d) {
    if (spec.cells[d] < 1)
      throw std::invalid_argument(
          fmt::format("box mesh: cells[{}] = {} must be >= 1", d, spec.cells[d]));
    if (!(spec.length[d] > 0))
      throw std::invalid_argument(
          fmt::format("box mesh: length[{}] = {} must be > 0", d, spec.length[d]));
    if (spec.periodic[d] && spec.cells[d] < 3)
      throw std::invalid_argument(fmt::format(
          "box mesh: periodic direction {} needs at least 3 cells, got {}", d, spec.cells[d]));
  }
  if (spec.perturbation < 0 || spec.perturbation > 0.4)
    throw std::invalid_argument(
        fmt::format("box mesh: perturbation = {} must be in [0, 0.4]", spec.perturbation));
  if (spec.cell_type == BoxCellType::mixed && spec.cells[0] < 4)
    throw std::invalid_argument("box mesh: a mixed mesh needs at least 4 cells along x");
  return BoxBuilder(spec).build();
}

}  // namespace valsalva::mesh
