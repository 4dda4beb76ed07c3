// Gmsh import of hexahedral solid meshes: a box a x b x c meshed by the Gmsh API (transfinite
// quadrangles, recombined, extruded in layers -> hexahedra; order 2 -> 27-node hexahedra),
// written to .msh and read back. Counts follow from the structured grid, the volume and the
// physical-surface area from the box, and a homogeneous stretch gives zero internal force at
// every node not on the boundary (patch test), which checks the node order of every element.
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <filesystem>

#include "io/solid_gmsh_reader.hpp"
#include "mesh/gmsh_reader.hpp"
#include "structure/loads.hpp"
#include "structure/solid_forces.hpp"
#include "tests/structure/solid_volume.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

constexpr double a = 2e-3, b = 1e-3, c = 0.3e-3;
constexpr int nx = 4, ny = 3, nz = 2;

fs::path make_box(int order, bool tets = false) {
  const fs::path dir = fs::path("test_output") / "solid_gmsh";
  fs::create_directories(dir);
  const fs::path file = dir / fmt::format("box_o{}{}.msh", order, tets ? "_tet" : "");
  mesh::GmshSession session;
  namespace g = gmsh::model::geo;
  const int p1 = g::addPoint(0, 0, 0), p2 = g::addPoint(a, 0, 0), p3 = g::addPoint(a, b, 0),
            p4 = g::addPoint(0, b, 0);
  const int l1 = g::addLine(p1, p2), l2 = g::addLine(p2, p3), l3 = g::addLine(p3, p4),
            l4 = g::addLine(p4, p1);
  const int s = g::addPlaneSurface({g::addCurveLoop({l1, l2, l3, l4})});
  g::mesh::setTransfiniteCurve(l1, nx + 1);
  g::mesh::setTransfiniteCurve(l3, nx + 1);
  g::mesh::setTransfiniteCurve(l2, ny + 1);
  g::mesh::setTransfiniteCurve(l4, ny + 1);
  g::mesh::setTransfiniteSurface(s);
  if (!tets) g::mesh::setRecombine(2, s);
  gmsh::vectorpair out;
  g::extrude({{2, s}}, 0, 0, c, out, {nz}, {}, !tets);
  g::synchronize();
  gmsh::model::addPhysicalGroup(2, {s}, 1);
  gmsh::model::setPhysicalName(2, 1, "bottom");
  gmsh::model::addPhysicalGroup(2, {out[0].second}, 2);  // top, left unnamed
  gmsh::model::addPhysicalGroup(3, {out[1].second}, 3);
  gmsh::model::addPhysicalGroup(1, {l4}, 4);
  gmsh::model::setPhysicalName(1, 4, "edge_x0");
  gmsh::model::mesh::generate(3);
  if (order == 2) gmsh::model::mesh::setOrder(2);
  gmsh::write(file.string());
  return file;
}

double volume(const structure::SolidMesh& m) {
  return structure::testing::solid_volume(m);
}

}  // namespace

TEST_CASE("solid Gmsh import: hex8 and hex27 boxes") {
  for (int order : {1, 2}) {
    CAPTURE(order);
    const structure::SolidMesh m = io::read_solid_gmsh(make_box(order));
    CHECK(m.order == (order == 1 ? structure::HexOrder::q1 : structure::HexOrder::q2));
    CHECK(m.num_elements() == nx * ny * nz);
    CHECK(m.num_nodes() == (order * nx + 1) * (order * ny + 1) * (order * nz + 1));
    CHECK(volume(m) == doctest::Approx(a * b * c).epsilon(1e-12));
    REQUIRE(m.surface_sets.count("bottom"));
    CHECK(m.surface_set("bottom").size() == nx * ny);
    CHECK(structure::surface_area(m, m.surface_set("bottom"), m.X) ==
          doctest::Approx(a * b).epsilon(1e-12));
    CHECK(m.surface_set("physical2_2").size() == nx * ny);  // unnamed top surface
    for (const auto& fr : m.surface_set("physical2_2"))
      CHECK(structure::hex_face(fr.face).axis == 2);
    CHECK(m.node_set("bottom").size() == std::size_t((order * nx + 1) * (order * ny + 1)));
    for (int n : m.node_set("bottom")) CHECK(std::abs(m.X(2, n)) < 1e-15);
    CHECK(m.node_set("edge_x0").size() == std::size_t(order * ny + 1));
    CHECK(m.node_set("physical3_3").size() == std::size_t(m.num_nodes()));
    // Patch test: homogeneous stretch, interior nodes carry no force.
    const auto mat = structure::make_neo_hookean(2.4e6, 1.6e6);
    const structure::SolidForces forces(m, *mat);
    Eigen::Matrix3Xd x = m.X, f(3, m.num_nodes());
    x.row(0) *= 1.1;
    x.row(1) *= 0.95;
    forces.internal_forces(x, f);
    const double scale = f.cwiseAbs().maxCoeff();
    CHECK(scale > 0);
    int interior = 0;
    for (int n = 0; n < m.num_nodes(); ++n) {
      const auto X = m.X.col(n);
      const bool inside = X[0] > 1e-9 && X[0] < a - 1e-9 && X[1] > 1e-9 && X[1] < b - 1e-9 &&
                          X[2] > 1e-9 && X[2] < c - 1e-9;
      if (!inside) continue;
      ++interior;
      CHECK(f.col(n).norm() < 1e-10 * scale);
    }
    CHECK(interior == (order * nx - 1) * (order * ny - 1) * (order * nz - 1));
  }
}

TEST_CASE("solid Gmsh import: bad input is named") {
  CHECK_THROWS_WITH_AS(io::read_solid_gmsh("test_output/no_such_file.msh"),
                       doctest::Contains("no_such_file.msh"), mesh::MeshFileError);
  CHECK_THROWS_WITH_AS(io::read_solid_gmsh(make_box(1, true)), doctest::Contains("Tetrahedron"),
                       mesh::MeshFileError);
}
