// Gmsh/OpenCASCADE pipe mesh: patch geometry, volume against the cylinder, determinism.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "mesh/mesh_check.hpp"
#include "mesh/pipe_generator.hpp"

using namespace valsalva;

TEST_CASE("pipe mesh: patches on the right surfaces, valid tetrahedra, inscribed volume") {
  const double r = 0.01, length = 0.05, h = 0.0025;
  const mesh::Mesh mesh = mesh::generate_pipe_mesh(r, length, h);
  MESSAGE("pipe mesh: ", mesh.num_nodes(), " nodes, ", mesh.num_cells(), " tetrahedra");
  CHECK(mesh.patch_names == std::vector<std::string>{"inlet", "outlet", "wall"});
  CHECK(mesh.region_names == std::vector<std::string>{"fluid"});
  for (auto t : mesh.cell_types) REQUIRE(t == mesh::CellType::tetra);
  CHECK_NOTHROW(mesh::check_mesh(mesh));

  // Nodes of each patch lie on its surface; inlet rim nodes counted for the polygon area.
  const int inlet = mesh.patch_index("inlet"), outlet = mesh.patch_index("outlet");
  std::set<mesh::GlobalIndex> rim;
  double max_off = 0;
  std::vector<double> area(3, 0.0);
  for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    const int p = mesh.face_patches[f];
    area[p] += mesh::face_area(mesh, mesh.face(f)).norm();
    for (auto n : mesh.face(f)) {
      const auto& x = mesh.nodes[n];
      const double radius = std::hypot(x.x(), x.y());
      if (p == inlet) {
        max_off = std::max(max_off, std::abs(x.z()));
        if (std::abs(radius - r) < 1e-9 * r) rim.insert(n);
      } else if (p == outlet) {
        max_off = std::max(max_off, std::abs(x.z() - length));
      } else {
        max_off = std::max(max_off, std::abs(radius - r));
      }
    }
  }
  CHECK(max_off < 1e-12);
  // The inlet is a plane triangulation of the regular polygon inscribed in the circle.
  const double n_rim = static_cast<double>(rim.size());
  REQUIRE(n_rim >= 2 * std::numbers::pi * r / h);
  CHECK(
      area[inlet] ==
      doctest::Approx(0.5 * n_rim * r * r * std::sin(2 * std::numbers::pi / n_rim)).epsilon(1e-12));
  CHECK(area[outlet] == doctest::Approx(area[inlet]).epsilon(1e-12));
  // Wall and volume: the triangulated surface lies inside the cylinder; the relative deficit is
  // that of an inscribed polygon, 1 - sin(t)/t ~ t^2/6 with chord angle t = 2 pi / n_rim, and the
  // wall triangles joining rim nodes at different z add to it (factor 2 allowed).
  const double t = 2 * std::numbers::pi / n_rim, deficit = t * t / 6;
  double volume = 0;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) volume += mesh::cell_volume(mesh, c);
  const double exact = std::numbers::pi * r * r * length;
  MESSAGE("volume deficit ", 1 - volume / exact, " (polygon deficit ", deficit, ")");
  CHECK(volume < exact);
  CHECK(1 - volume / exact < 2 * deficit);
  const double wall = 2 * std::numbers::pi * r * length;
  CHECK(area[mesh.patch_index("wall")] < wall);
  CHECK(1 - area[mesh.patch_index("wall")] / wall < 2 * deficit);
}

TEST_CASE("pipe mesh is deterministic and rejects bad arguments") {
  const mesh::Mesh a = mesh::generate_pipe_mesh(0.5, 1.0, 0.2);
  const mesh::Mesh b = mesh::generate_pipe_mesh(0.5, 1.0, 0.2);
  CHECK(a.nodes == b.nodes);
  CHECK(a.cell_nodes == b.cell_nodes);
  CHECK(a.face_nodes == b.face_nodes);
  CHECK_THROWS_AS(mesh::generate_pipe_mesh(0.0, 1.0, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(mesh::generate_pipe_mesh(1.0, -1.0, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(mesh::generate_pipe_mesh(1.0, 1.0, NAN), std::invalid_argument);
}

TEST_CASE("pipe mesh: wall-graded size refines only near the wall") {
  const double r = 0.5, length = 1.0, h = 0.1;
  mesh::PipeMeshOptions graded;
  graded.wall_size = 0.5 * h, graded.wall_distance = h;
  const mesh::Mesh uniform = mesh::generate_pipe_mesh(r, length, h);
  const mesh::Mesh mesh = mesh::generate_pipe_mesh(r, length, h, graded);
  CHECK_NOTHROW(mesh::check_mesh(mesh));
  // Half the size on the wall surface: about 4x its nodes; the core r < r - 2h keeps size h.
  const auto count = [&](const mesh::Mesh& m, bool wall) {
    int n = 0;
    for (const auto& x : m.nodes) {
      const double s = std::hypot(x.x(), x.y());
      n += wall ? (std::abs(s - r) < 1e-9 && x.z() > h && x.z() < length - h)
                : (s < r - 2 * h && x.z() > h && x.z() < length - h);
    }
    return n;
  };
  MESSAGE("wall nodes ", count(uniform, true), " -> ", count(mesh, true), ", core nodes ",
          count(uniform, false), " -> ", count(mesh, false));
  CHECK(count(mesh, true) > 3 * count(uniform, true));
  CHECK(count(mesh, false) < 1.3 * count(uniform, false));
  graded.wall_distance = 0;
  CHECK_THROWS_AS(mesh::generate_pipe_mesh(r, length, h, graded), std::invalid_argument);
}
