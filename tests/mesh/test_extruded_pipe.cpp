// Extruded inlet/outlet pipe (mesh/extruded_pipe_generator.hpp): positive tetrahedra, patches on
// their surfaces, inlet/outlet areas and volume against the inscribed chord polygon of the
// circle, and the wall grading's first row of nodes where it was asked for.
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>
#include <numbers>

#include "mesh/extruded_pipe_generator.hpp"
#include "mesh/mesh_check.hpp"

using namespace valsalva;

namespace {

struct Measured {
  std::vector<double> area;  // per patch
  double volume = 0, off = 0, min_cell = 1, first_row = 1;
};

Measured measure(const mesh::Mesh& mesh, const mesh::ExtrudedPipeSpec& s) {
  Measured m;
  m.area.assign(mesh.patch_names.size(), 0.0);
  const int inlet = mesh.patch_index("inlet"), outlet = mesh.patch_index("outlet");
  std::vector<bool> on_wall(mesh.num_nodes(), false);
  for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f) {
    const int p = mesh.face_patches[f];
    m.area[p] += mesh::face_area(mesh, mesh.face(f)).norm();
    for (auto n : mesh.face(f)) {
      const auto& x = mesh.nodes[n];
      const double off = p == inlet    ? std::abs(x.z())
                         : p == outlet ? std::abs(x.z() - s.length)
                                       : std::abs(std::hypot(x.x(), x.y()) - s.radius);
      m.off = std::max(m.off, off);
      if (p != inlet && p != outlet) on_wall[n] = true;
    }
  }
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const double v = mesh::cell_volume(mesh, c);
    m.volume += v;
    m.min_cell = std::min(m.min_cell, v);
  }
  for (mesh::GlobalIndex n = 0; n < mesh.num_nodes(); ++n)
    if (!on_wall[n])
      m.first_row =
          std::min(m.first_row, s.radius - std::hypot(mesh.nodes[n].x(), mesh.nodes[n].y()));
  return m;
}

}  // namespace

TEST_CASE("extruded pipe: tetrahedra, patches, chord-polygon areas and volume, wall grading") {
  mesh::ExtrudedPipeSpec base;
  base.radius = 0.01, base.length = 0.02, base.target_size = 0.0025, base.layer_height = 0.002;
  auto isotropic = base, rows = base;
  isotropic.grading.wall_size = 0.001, isotropic.grading.wall_distance = 0.002;
  rows.grading.layer_first = 0.0004, rows.grading.layer_ratio = 1.3;
  rows.grading.layer_thickness = 0.0015;
  for (const auto& [name, spec, first_row] : {std::tuple{std::string("ungraded"), base, 0.0},
                                              {"isotropic", isotropic, 0.0},
                                              {"rows", rows, rows.grading.layer_first}}) {
    CAPTURE(name);
    const auto mesh = mesh::generate_extruded_pipe_mesh(spec);
    MESSAGE(name, ": ", mesh.num_nodes(), " nodes, ", mesh.num_cells(), " tetrahedra");
    for (auto t : mesh.cell_types) REQUIRE(t == mesh::CellType::tetra);
    CHECK_NOTHROW(mesh::check_mesh(mesh));
    CHECK(mesh.region_names == std::vector<std::string>{"fluid"});
    const auto m = measure(mesh, spec);
    CHECK(m.min_cell > 0);
    CHECK(m.off < 1e-12);
    // The sections are one triangulated polygon inscribed in the circle with chords no longer
    // than ~ the size: area deficit below pi R^2 t^2 / 6 for chord angle t = size / R (1.5x
    // margin for the chord scatter of the 1D mesher), as the periodic pipe's test.
    const double disc = std::numbers::pi * spec.radius * spec.radius;
    const double t = spec.target_size / spec.radius, deficit = 1.5 * disc * t * t / 6;
    const double a_in = m.area[mesh.patch_index("inlet")];
    CHECK(a_in < disc);
    CHECK(disc - a_in < deficit);
    CHECK(m.area[mesh.patch_index("outlet")] == doctest::Approx(a_in).epsilon(1e-12));
    // Prism layers: the volume is the section times the length, exactly up to round-off.
    CHECK(m.volume == doctest::Approx(a_in * spec.length).epsilon(1e-12));
    // The wall: the chord perimeter times the length, below 2 pi R L by at most ~t^2 / 6.
    const double wall = m.area[mesh.patch_index("wall")], side = 2 * std::numbers::pi * spec.radius;
    CHECK(wall < side * spec.length);
    CHECK(side * spec.length - wall < 1.5 * side * spec.length * t * t / 6);
    // The first interior row: at the BoundaryLayer's first height (the normal of a circle is
    // radial), else no closer than a fraction of the wall size asked for.
    if (first_row > 0)
      CHECK(m.first_row == doctest::Approx(first_row).epsilon(0.02));
    else
      CHECK(m.first_row >
            0.3 * (spec.grading.wall_size > 0 ? spec.grading.wall_size : spec.target_size));
    if (spec.grading.wall_size > 0) CHECK(m.first_row < spec.grading.wall_size);
    // Gmsh's Delaunay disks repeat; its BoundaryLayer rows do not (hence rank 0's disk is sent
    // to the other ranks, checked at np 2 below).
    if (first_row == 0) {
      const auto again = mesh::generate_extruded_pipe_mesh(spec);
      CHECK(again.nodes == mesh.nodes);
      CHECK(again.cell_nodes == mesh.cell_nodes);
    }
    // Every rank of the world holds rank 0's mesh.
    const auto shared = mesh::generate_extruded_pipe_mesh(spec, MPI_COMM_WORLD);
    std::vector<double> mine, first;
    for (const auto& x : shared.nodes) mine.insert(mine.end(), {x.x(), x.y(), x.z()});
    first = mine;
    long count = static_cast<long>(first.size());
    MPI_Bcast(&count, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    first.resize(count);
    MPI_Bcast(first.data(), static_cast<int>(count), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    CHECK(first == mine);
  }
  auto bad = base;
  bad.length = -1;
  CHECK_THROWS_WITH_AS(mesh::generate_extruded_pipe_mesh(bad), doctest::Contains("length"),
                       std::invalid_argument);
  bad = base;
  bad.grading.wall_size = 0.001;  // no wall_distance
  CHECK_THROWS_AS(mesh::generate_extruded_pipe_mesh(bad), std::invalid_argument);
}
