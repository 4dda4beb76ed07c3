// DFG cylinder-channel slab mesh and the conforming prism split it relies on.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <tuple>
#include <vector>

#include "mesh/box_generator.hpp"
#include "mesh/cylinder_channel_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/prism_split.hpp"
#include "scene/mesh_source.hpp"
#include "scene/scene.hpp"

using namespace valsalva;

namespace {

double total_volume(const mesh::Mesh& mesh) {
  double v = 0;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) v += mesh::cell_volume(mesh, c);
  return v;
}

// A coarse channel with a refinement box behind the cylinder.
mesh::CylinderChannelSpec refined_spec() {
  mesh::CylinderChannelSpec spec;
  spec.size_near = 0.02;
  spec.size_far = 0.08;
  spec.box_size = 0.01;
  spec.box_x0 = 0.3;
  spec.box_x1 = 0.7;
  spec.box_y0 = 0.15;
  spec.box_y1 = 0.25;
  return spec;
}

}  // namespace

TEST_CASE("prism split: conforming tetrahedra of the same volume, quad faces cut alike") {
  mesh::BoxSpec spec;
  spec.cells = {4, 3, 5};
  spec.length = Eigen::Vector3d(1.0, 0.7, 1.3);
  spec.cell_type = mesh::BoxCellType::prism;
  spec.perturbation = 0.2;
  const auto prisms = mesh::generate_box(spec);
  const auto tets = mesh::split_prisms_to_tetrahedra(prisms);
  CHECK(tets.num_cells() == 3 * prisms.num_cells());
  for (auto t : tets.cell_types) REQUIRE(t == mesh::CellType::tetra);
  // check_mesh rejects non-conforming faces (a face seen once and untagged) and inverted cells.
  CHECK_NOTHROW(mesh::check_mesh(tets));
  CHECK(total_volume(tets) == doctest::Approx(total_volume(prisms)).epsilon(1e-13));
  for (mesh::GlobalIndex c = 0; c < tets.num_cells(); ++c) CHECK(mesh::cell_volume(tets, c) > 0);
}

TEST_CASE("prism split refuses hexahedra") {
  mesh::BoxSpec spec;
  spec.cells = {2, 2, 2};
  CHECK_THROWS_AS(mesh::split_prisms_to_tetrahedra(mesh::generate_box(spec)), mesh::MeshError);
}

TEST_CASE("cylinder channel: patches, volume, periodic slab metrics") {
  mesh::CylinderChannelSpec spec;
  spec.size_near = 0.02;
  spec.size_far = 0.08;
  auto mesh = mesh::generate_cylinder_channel_mesh(spec);
  MESSAGE("cylinder channel: ", mesh.num_nodes(), " nodes, ", mesh.num_cells(), " tetrahedra");
  for (const char* p : {"inlet", "outlet", "wall", "cylinder", "front", "back"})
    CHECK_MESSAGE(mesh.patch_index(p) >= 0, p);
  CHECK_NOTHROW(mesh::check_mesh(mesh));
  // Volume: channel minus the inscribed polygon of the cylinder (deficit below (2 pi/n)^2/6 of
  // the disc with n >= pi d / size_near chords), times the thickness.
  const double r = spec.diameter / 2;
  const double disc = std::numbers::pi * r * r;
  const double exact = (spec.length * spec.height - disc) * spec.thickness;
  const double n_chords = std::numbers::pi * spec.diameter / spec.size_near;
  const double t = 2 * std::numbers::pi / n_chords;
  const double volume = total_volume(mesh);
  MESSAGE("volume error ", volume / exact - 1);
  CHECK(volume > exact);
  CHECK(volume - exact < 1.5 * disc * t * t / 6 * spec.thickness);
  // Nodes of the cylinder patch lie on the circle; front/back pair as periodic.
  const int cyl = mesh.patch_index("cylinder");
  double off = 0;
  for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f)
    if (mesh.face_patches[f] == cyl)
      for (auto n : mesh.face(f))
        off = std::max(off, std::abs(std::hypot(mesh.nodes[n].x() - spec.centre_x,
                                                mesh.nodes[n].y() - spec.centre_y) -
                                     r));
  CHECK(off < 1e-9 * r);
  mesh.periodic.push_back({"front", "back", Eigen::Vector3d(0, 0, spec.thickness)});
  const auto metrics = mesh::compute_dual_metrics(mesh);
  double dual = 0;
  for (double v : metrics.volume) dual += v;
  CHECK(dual == doctest::Approx(volume).epsilon(1e-12));
  // Deterministic: the same spec gives the same mesh.
  const auto again = mesh::generate_cylinder_channel_mesh(spec);
  CHECK(again.num_cells() == mesh.num_cells());
  CHECK(again.nodes == mesh.nodes);
}

TEST_CASE("cylinder channel: every layer's prisms are cut alike") {
  // Each layer's tetrahedra, as (x, y, layer offset) node patterns, repeat the first layer's:
  // Gmsh cuts the extruded prisms the same way in every layer, so the slab is z-invariant (a
  // z-invariant flow stays so).
  mesh::CylinderChannelSpec spec;
  spec.size_near = 0.02;
  spec.size_far = 0.08;
  const double dz = spec.thickness / spec.layers;
  using Pattern = std::vector<std::tuple<double, double, long>>;
  std::vector<std::multiset<Pattern>> layers(spec.layers);
  const auto mesh = mesh::generate_cylinder_channel_mesh(spec);
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    Pattern p;
    long base = spec.layers;
    for (auto n : mesh.cell(c)) base = std::min(base, std::lround(mesh.nodes[n].z() / dz));
    for (auto n : mesh.cell(c))
      p.emplace_back(mesh.nodes[n].x(), mesh.nodes[n].y(),
                     std::lround(mesh.nodes[n].z() / dz) - base);
    std::sort(p.begin(), p.end());
    layers.at(base).insert(p);
  }
  CHECK(layers[0].size() * spec.layers == static_cast<std::size_t>(mesh.num_cells()));
  for (int l = 1; l < spec.layers; ++l) CHECK(layers[l] == layers[0]);
  spec.split = false;  // the unsplit slab: prisms
  const auto prisms = mesh::generate_cylinder_channel_mesh(spec);
  CHECK(prisms.num_cells() * 3 == mesh.num_cells());
  for (auto t : prisms.cell_types) REQUIRE(t == mesh::CellType::prism);
  CHECK_NOTHROW(mesh::check_mesh(prisms));
}

TEST_CASE("cylinder channel: refinement box") {
  auto spec = refined_spec();
  const auto mesh = mesh::generate_cylinder_channel_mesh(spec);
  CHECK_NOTHROW(mesh::check_mesh(mesh));
  // Node spacing inside the box: the mean length of the in-plane edges (z-extrusion edges
  // excluded) between nodes in the box's core is about box_size, well below size_near.
  double sum = 0;
  int count = 0;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto cell = mesh.cell(c);
    for (std::size_t i = 0; i < cell.size(); ++i)
      for (std::size_t j = i + 1; j < cell.size(); ++j) {
        const Eigen::Vector3d a = mesh.nodes[cell[i]], b = mesh.nodes[cell[j]];
        const Eigen::Vector3d m = (a + b) / 2;
        if (std::abs(a.z() - b.z()) > 1e-12 || m.x() < 0.4 || m.x() > 0.6 || m.y() < 0.17 ||
            m.y() > 0.23)
          continue;
        sum += (a - b).norm();
        ++count;
      }
  }
  REQUIRE(count > 0);
  MESSAGE("mean in-plane edge in the box ", sum / count);
  CHECK(sum / count < 1.3 * spec.box_size);
  CHECK(sum / count > 0.7 * spec.box_size);
  spec.box_x1 = 3.0;  // outside the channel
  CHECK_THROWS_WITH_AS(mesh::generate_cylinder_channel_mesh(spec),
                       doctest::Contains("refinement box"), std::invalid_argument);
}

TEST_CASE("cylinder channel scene keys: the refinement box reaches the generator") {
  const std::string head = R"(
[mesh]
source = "cylinder_channel"
[mesh.cylinder_channel]
size_near = 0.02
size_far = 0.08
)";
  const std::string box = R"(box_size = 0.01
box_x0 = 0.3
box_y0 = 0.15
box_y1 = 0.25
box_transition = 0.15
)";
  auto spec = refined_spec();
  spec.box_transition = 0.15;
  const auto direct = mesh::generate_cylinder_channel_mesh(spec);
  const auto scene = scene::parse_scene(head + box + "box_x1 = 0.7\n", "t.toml");
  const auto from_scene = scene::build_mesh(scene);
  CHECK(from_scene.nodes.size() == direct.nodes.size());
  CHECK(from_scene.num_cells() == direct.num_cells());
  // Without the box keys the mesh is the plain (coarser) channel.
  const auto plain = scene::build_mesh(scene::parse_scene(head, "t.toml"));
  CHECK(plain.nodes.size() < direct.nodes.size());
  // A box outside the channel is refused with the scene table named.
  const auto bad = scene::parse_scene(head + box + "box_x1 = 3.0\n", "t.toml");
  CHECK_THROWS_WITH(scene::build_mesh(bad), doctest::Contains("mesh.cylinder_channel"));
}
