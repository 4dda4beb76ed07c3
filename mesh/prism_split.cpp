// Prism -> tetrahedra split; see prism_split.hpp.
#include "mesh/prism_split.hpp"

#include <array>
#include <string>

#include "mesh/mesh_check.hpp"

namespace valsalva::mesh {

namespace {

using mesh::GlobalIndex;

double signed_volume(const mesh::Mesh& mesh, const std::array<GlobalIndex, 4>& t) {
  const auto& x = mesh.nodes;
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]) / 6;
}

// The three tetrahedra of a prism (bottom a0 a1 a2, top b_i above a_i). With the vertical edges
// taken in the order i1, i2, i3, the staircase split (a_i1 a_i2 a_i3 b_i1), (a_i2 a_i3 b_i1
// b_i2), (a_i3 b_i1 b_i2 b_i3) cuts the quad face of edges ip before iq along a_iq - b_ip. The
// order is read off the faces' smallest-index diagonals; a cyclic order has no split.
std::array<std::array<GlobalIndex, 4>, 3> split_prism(std::span<const GlobalIndex> p,
                                                      GlobalIndex cell) {
  // before[i][j]: vertical edge i precedes j.
  bool before[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const GlobalIndex ai = p[i], aj = p[j], bi = p[i + 3], bj = p[j + 3];
      const GlobalIndex m = std::min({ai, aj, bi, bj});
      // The diagonal through m is a_j-b_i (i first) when m is a_j or b_i.
      const bool i_first = (m == aj || m == bi);
      before[i][j] = i_first;
      before[j][i] = !i_first;
    }
  std::array<int, 3> order{};
  int found = 0;
  for (int first = 0; first < 3; ++first)
    if (before[first][(first + 1) % 3] && before[first][(first + 2) % 3]) {
      const int s = (first + 1) % 3, t = (first + 2) % 3;
      order = before[s][t] ? std::array{first, s, t} : std::array{first, t, s};
      ++found;
    }
  if (found != 1)
    throw mesh::MeshError("split_prisms_to_tetrahedra: prism " + std::to_string(cell) +
                          " has cyclic face diagonals and cannot be split without a new node");
  const auto a = [&](int k) { return p[order[k]]; };
  const auto b = [&](int k) { return p[order[k] + 3]; };
  return {{{a(0), a(1), a(2), b(0)}, {a(1), a(2), b(0), b(1)}, {a(2), b(0), b(1), b(2)}}};
}

}  // namespace

mesh::Mesh split_prisms_to_tetrahedra(const mesh::Mesh& mesh) {
  mesh::Mesh out;
  out.nodes = mesh.nodes;
  out.region_names = mesh.region_names;
  out.patch_names = mesh.patch_names;
  out.periodic = mesh.periodic;
  out.source = mesh.source;
  for (GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    const auto type = mesh.cell_types[c];
    if (type == mesh::CellType::tetra) {
      out.add_cell(type, nodes, mesh.cell_regions[c]);
    } else if (type == mesh::CellType::prism) {
      for (auto t : split_prism(nodes, c)) {
        if (signed_volume(out, t) < 0) std::swap(t[0], t[1]);
        out.add_cell(mesh::CellType::tetra, t, mesh.cell_regions[c]);
      }
    } else {
      throw mesh::MeshError("split_prisms_to_tetrahedra: " + mesh.source + " cell " +
                            std::to_string(c) + " is a " + mesh::name(type) +
                            "; only tetrahedra and prisms can be split conformingly here");
    }
  }
  for (GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    const auto q = mesh.face(f);
    if (q.size() == 3) {
      out.add_face(q, mesh.face_patches[f]);
      continue;
    }
    // Quad q0 q1 q2 q3 (cyclic): cut along the diagonal through the smallest node, keeping the
    // orientation of the quad.
    int m = 0;
    for (int i = 1; i < 4; ++i)
      if (q[i] < q[m]) m = i;
    const std::array<GlobalIndex, 3> t1{q[m], q[(m + 1) % 4], q[(m + 2) % 4]};
    const std::array<GlobalIndex, 3> t2{q[m], q[(m + 2) % 4], q[(m + 3) % 4]};
    out.add_face(t1, mesh.face_patches[f]);
    out.add_face(t2, mesh.face_patches[f]);
  }
  return out;
}

}  // namespace valsalva::mesh
