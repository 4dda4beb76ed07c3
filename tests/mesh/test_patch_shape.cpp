// Circularity of boundary patches (mesh/patch_shape.hpp), the test behind refusing a Poiseuille or
// Womersley profile on a non-circular inlet: Gmsh pipe inlets down to a few elements per
// diameter stay below the limit, box faces (squares, rectangles) and the pipe's closed wall are
// above it.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "mesh/box_generator.hpp"
#include "mesh/patch_shape.hpp"
#include "mesh/pipe_generator.hpp"

using namespace valsalva;

TEST_CASE("Gmsh pipe inlets are circular at coarse sizes, their wall is not a section") {
  const double r = 0.005;
  for (double size : {0.0015, 0.0025, 0.004, 0.006}) {
    const auto mesh = mesh::generate_pipe_mesh(r, 0.02, size);
    const auto s = mesh::patch_shape(mesh, mesh.patch_index("inlet"));
    CAPTURE(size);
    MESSAGE("pipe D/size = ", 2 * r / size, ": circularity ", s.circularity);
    CHECK(s.circularity >= 1.0);
    CHECK(s.circularity < mesh::max_circularity);
    CHECK(s.max_radius == doctest::Approx(r).epsilon(1e-6));
    CHECK(s.area <= std::numbers::pi * r * r);
    const auto wall = mesh::patch_shape(mesh, mesh.patch_index("wall"));
    CHECK(wall.circularity > mesh::max_circularity);
  }
}

TEST_CASE("box faces: a square is 1.253, a 2:1 rectangle 1.40, both refused") {
  mesh::BoxSpec spec;
  spec.cells = {4, 2, 3};
  spec.length = {2.0, 1.0, 1.0};
  const auto mesh = mesh::generate_box(spec);
  const auto square = mesh::patch_shape(mesh, mesh.patch_index("xmin"));  // 1 x 1 in y, z
  CHECK(square.area == doctest::Approx(1.0));
  CHECK(square.circularity == doctest::Approx(std::sqrt(std::numbers::pi / 2)));
  const auto oblong = mesh::patch_shape(mesh, mesh.patch_index("ymin"));  // 2 x 1 in x, z
  CHECK(oblong.circularity == doctest::Approx(std::sqrt(1.25) / std::sqrt(2 / std::numbers::pi)));
  for (const auto& s : {square, oblong}) CHECK(s.circularity > mesh::max_circularity);
}
