// Periodic extruded pipe mesh (mesh/periodic_pipe_generator.hpp): valid prisms and split
// tetrahedra, the inscribed-polygon volume, wall nodes on the circle, identical layers.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "mesh/dual_metrics.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/periodic_pipe_generator.hpp"

using namespace valsalva;

TEST_CASE("periodic pipe: prisms and split tetrahedra, volume, wall, identical layers") {
  mesh::PeriodicPipeSpec spec;
  spec.radius = 0.01, spec.target_size = 0.002, spec.layers = 4, spec.length = 4 * 0.002;
  for (bool split : {false, true}) {
    spec.split = split;
    const auto mesh = mesh::generate_periodic_pipe_mesh(spec);
    CAPTURE(split);
    for (auto t : mesh.cell_types)
      REQUIRE(t == (split ? mesh::CellType::tetra : mesh::CellType::prism));
    CHECK_NOTHROW(mesh::check_mesh(mesh));
    double volume = 0;
    for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
      CHECK(mesh::cell_volume(mesh, c) > 0);
      volume += mesh::cell_volume(mesh, c);
    }
    // The disk is an inscribed polygon of n >= 2 pi R / size chords: area deficit below
    // pi R^2 (2 pi / n)^2 / 6.
    const double disc = std::numbers::pi * spec.radius * spec.radius;
    const double t = spec.target_size / spec.radius;
    CHECK(volume < disc * spec.length);
    CHECK(disc * spec.length - volume < 1.5 * disc * t * t / 6 * spec.length);
    const int wall = mesh.patch_index("wall");
    double off = 0;
    for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f)
      if (mesh.face_patches[f] == wall)
        for (auto n : mesh.face(f))
          off = std::max(off,
                         std::abs(std::hypot(mesh.nodes[n].x(), mesh.nodes[n].y()) - spec.radius));
    CHECK(off < 1e-9 * spec.radius);
    // Layer l is layer 0 shifted by l * length / layers, node by node.
    const auto per_layer = mesh.num_nodes() / (spec.layers + 1);
    REQUIRE(per_layer * (spec.layers + 1) == mesh.num_nodes());
    for (mesh::GlobalIndex a = 0; a < mesh.num_nodes(); ++a) {
      const auto& x = mesh.nodes[a];
      const auto& x0 = mesh.nodes[a % per_layer];
      REQUIRE(x.head<2>() == x0.head<2>());
    }
    // zmin/zmax pair as periodic; the dual volumes add up to the cell volumes.
    const auto metrics = mesh::compute_dual_metrics(mesh);
    double dual = 0;
    for (double v : metrics.volume) dual += v;
    CHECK(dual == doctest::Approx(volume).epsilon(1e-12));
    CHECK(metrics.num_nodes() == per_layer * spec.layers);
  }
  spec.layers = 2;
  CHECK_THROWS_WITH_AS(mesh::generate_periodic_pipe_mesh(spec), doctest::Contains("layers = 2"),
                       std::invalid_argument);
}
