// mesh_info: counts, patch areas, volumes, dual volumes and element quality against values
// worked out by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "mesh/dual_metrics.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/mesh_info.hpp"

using namespace valsalva;
using mesh::CellType;
using mesh::GlobalIndex;

namespace {

mesh::Mesh one_cell(CellType type, std::vector<Eigen::Vector3d> nodes) {
  mesh::Mesh mesh;
  mesh.nodes = std::move(nodes);
  std::vector<GlobalIndex> cell(mesh.nodes.size());
  for (std::size_t k = 0; k < cell.size(); ++k) cell[k] = static_cast<GlobalIndex>(k);
  mesh.add_cell(type, cell, mesh.add_region("fluid"));
  return mesh;
}

}  // namespace

TEST_CASE("quality measures are 1 for the ideal shapes and follow the closed forms") {
  const double s3 = std::sqrt(3.0), h = 1 / std::sqrt(2.0);
  auto regular_tet =
      one_cell(CellType::tetra,
               {{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}, {0.5, s3 / 6, std::sqrt(2.0 / 3.0)}});
  CHECK(mesh::cell_quality(regular_tet, 0) == doctest::Approx(1.0).epsilon(1e-14));
  std::swap(regular_tet.cell_nodes[1], regular_tet.cell_nodes[2]);  // inverted: negative
  CHECK(mesh::cell_quality(regular_tet, 0) == doctest::Approx(-1.0).epsilon(1e-14));
  const double shear = 0.75;
  std::vector<Eigen::Vector3d> hex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  CHECK(mesh::cell_quality(one_cell(CellType::hexa, hex), 0) ==
        doctest::Approx(1.0).epsilon(1e-14));
  for (auto& x : hex) x.x() += shear * x.z();  // every corner: det 1, one edge sqrt(1 + s^2)
  CHECK(mesh::cell_quality(one_cell(CellType::hexa, hex), 0) ==
        doctest::Approx(1 / std::sqrt(1 + shear * shear)).epsilon(1e-14));
  const auto prism =
      one_cell(CellType::prism,
               {{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}, {0, 0, 2}, {1, 0, 2}, {0.5, s3 / 2, 2}});
  CHECK(mesh::cell_quality(prism, 0) == doctest::Approx(1.0).epsilon(1e-14));
  const auto pyramid =
      one_cell(CellType::pyramid, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, h}});
  CHECK(mesh::cell_quality(pyramid, 0) == doctest::Approx(1.0).epsilon(1e-14));
}

TEST_CASE("mesh_info of the six-tetrahedron unit cube") {
  const auto file = std::filesystem::path(VALSALVA_SOURCE_DIR) / "tests/data/meshes/cube_tets.msh";
  const mesh::Mesh mesh = mesh::read_gmsh(file);
  const mesh::MeshInfo info = mesh::summarize_mesh(mesh);
  CHECK(info.nodes == 8);
  CHECK(info.cells_of_type[static_cast<int>(CellType::tetra)] == 6);
  REQUIRE(info.patches.size() == 1);
  CHECK(info.patches[0].name == "wall");
  CHECK(info.patches[0].faces == 12);
  CHECK(info.patches[0].area == doctest::Approx(6.0).epsilon(1e-14));
  CHECK(info.volume == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(info.min_cell_volume == doctest::Approx(1.0 / 6).epsilon(1e-14));
  CHECK(!info.min_dual_volume);
  // Each Kuhn tetrahedron has edges 1, 1, 1, sqrt2, sqrt2, sqrt3: sum l^2 = 10, V = 1/6.
  const auto& q = info.quality[static_cast<int>(CellType::tetra)];
  const double kuhn = 12 * std::pow(0.5, 2.0 / 3.0) / 10;
  CHECK(q.min == doctest::Approx(kuhn).epsilon(1e-14));
  CHECK(q.max == doctest::Approx(kuhn).epsilon(1e-14));
  CHECK(q.mean == doctest::Approx(kuhn).epsilon(1e-14));

  const mesh::DualMetrics metrics = mesh::compute_dual_metrics(mesh);
  const mesh::MeshInfo with_dual =
      mesh::summarize_mesh(mesh, std::span<const double>(metrics.volume));
  CHECK(*with_dual.dual_volume_sum == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(*with_dual.min_dual_volume > 0);

  const std::string text = mesh::mesh_info(mesh);
  MESSAGE(text);
  CHECK(text.find(file.string()) != std::string::npos);
  CHECK(text.find("tetrahedron           6") != std::string::npos);
  CHECK(text.find("mean ratio): min 0.7560") != std::string::npos);
  CHECK(text.find("patch  'wall'           12 faces, area 6 m^2") != std::string::npos);
  CHECK(text.find("volume 1 m^3") != std::string::npos);
  // The dual volumes tile the cube: their sum is its volume.
  CHECK(text.find("(sum 1 m^3)") != std::string::npos);
}

TEST_CASE("mesh_info refuses a bad mesh with the check_mesh error") {
  const auto file =
      std::filesystem::path(VALSALVA_SOURCE_DIR) / "tests/data/meshes/bad/inverted_tet.msh";
  const mesh::Mesh mesh = mesh::read_gmsh(file);
  CHECK_THROWS_WITH_AS(mesh::mesh_info(mesh), doctest::Contains("inverted cell 2"),
                       mesh::MeshError);
}
