// The three manufactured leaflets: element-count rule (the reference study's 384 / 1536 Q2
// hexahedra at 1 / 0.5 mm), sets per leaflet and their unions, the attachment on the frame's top
// edge, the volume of the scalloped cylindrical patches, the leaflets.msh round trip through
// io::read_solid_gmsh, and the per-leaflet submesh.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "mesh/gmsh_reader.hpp"
#include "tests/structure/solid_volume.hpp"
#include "valve/leaflet_mesh.hpp"

using namespace valsalva;

namespace {

using structure::testing::solid_volume;

const char* kSets[] = {"attachment", "free_edge", "aortic_face", "ventricular_face"};

}  // namespace

TEST_CASE("leaflet element counts follow the mesh size (reference M1 and M2)") {
  valve::ValveGeometry g;
  // 15 mm leaflets at 1.5 mesh_size: 480 elements at 1 mm (the reference M1's 12 mm-class
  // leaflets had 384), 1920 at 0.5 mm.
  CHECK(valve::leaflet_elements(g) == std::array<int, 2>{16, 10});
  CHECK(valve::valve_leaflets(g).num_elements() == 480);
  g.mesh_size = 0.5e-3;
  CHECK(valve::leaflet_elements(g) == std::array<int, 2>{32, 20});
  g.mesh_size = 3e-3;
  CHECK(valve::leaflet_elements(g) == std::array<int, 2>{5, 3});
  g.leaflet_height = 12e-3;
  g.mesh_size = 1e-3;
  CHECK(valve::valve_leaflets(g).num_elements() == 384);
}

TEST_CASE("valve leaflets: sets, attachment on the frame, volume") {
  valve::ValveGeometry g;
  g.free_edge_rise = 0;  // a flat free edge (the rise: next test)
  const structure::SolidMesh m = valve::valve_leaflets(g);
  const int per = (2 * 16 + 1) * (2 * 10 + 1) * 3;
  REQUIRE(m.num_nodes() == 3 * per);
  for (const char* set : kSets) {
    std::size_t nodes = 0, faces = 0;
    for (int i = 1; i <= 3; ++i) {
      const std::string name = "leaflet" + std::to_string(i) + "_" + set;
      CAPTURE(name);
      CHECK(!m.node_set(name).empty());
      nodes += m.node_set(name).size();
      faces += m.surface_set(name).size();
    }
    CHECK(m.node_set(set).size() == nodes);  // leaflets share no node
    CHECK(m.surface_set(set).size() == faces);
  }
  CHECK(m.surface_set("leaflet2_aortic_face").size() == 16 * 10);
  CHECK(m.surface_set("leaflet2_attachment").size() == 16 + 2 * 10);
  CHECK(m.surface_set("leaflet3_free_edge").size() == 16);

  // Faces: aortic (outer) at r = R_L + t/2, ventricular at R_L - t/2.
  auto radius = [&](int n) { return std::hypot(m.X(0, n), m.X(1, n)); };
  for (int n : m.node_set("aortic_face"))
    CHECK(radius(n) == doctest::Approx(g.leaflet_radius + g.leaflet_thickness / 2).epsilon(1e-12));
  for (int n : m.node_set("ventricular_face"))
    CHECK(radius(n) == doctest::Approx(g.leaflet_radius - g.leaflet_thickness / 2).epsilon(1e-12));
  // Attachment: every node on the frame's top edge (the scallop, z = frame_top(theta)) or on a
  // post's side face (angle = post edge, z within the commissure attachment below the free edge).
  int on_scallop = 0, on_post = 0;
  for (int n : m.node_set("attachment")) {
    const double th = std::atan2(m.X(1, n), m.X(0, n)), z = m.X(2, n);
    bool post_side = false;
    for (int k = 0; k < 3; ++k)
      for (double s : {-1.0, 1.0}) {
        const double edge = g.commissure_angle(k) + s * g.post_width() / 2;
        if (std::abs(std::remainder(th - edge, 2 * M_PI)) < 1e-9) post_side = true;
      }
    if (post_side) {
      ++on_post;
      CHECK(z >= g.free_edge_z() - g.commissure_attachment - 1e-12);
      CHECK(z <= g.free_edge_z() + 1e-12);
    } else {
      ++on_scallop;
      CHECK(z == doctest::Approx(g.frame_top(th)).epsilon(1e-10));
    }
  }
  CHECK(on_scallop == 3 * 3 * (2 * 16 - 1));  // scallop nodes except the two corners, 3 layers
  CHECK(on_post == 3 * 3 * 2 * (2 * 10 + 1));
  // Free edge at z_free.
  for (int n : m.node_set("free_edge")) CHECK(m.X(2, n) == doctest::Approx(g.free_edge_z()));

  // Volume: thickness x mid radius x integral over the span of (z_free - z_a), with z_a the
  // parabolic scallop (mean of q^2 over [-1, 1] = 1/3). Q2 elements map the arcs by quadratics
  // over up to 10 degrees each (the widest, at the leaflet centre, with the default side
  // grading): a relative volume error of order (10 deg)^4 / 100 ~ 1e-5.
  const double H = g.leaflet_height, a = g.commissure_attachment;
  const double exact =
      3 * g.leaflet_thickness * g.leaflet_radius * g.leaflet_span() * (H - (H - a) / 3);
  CHECK(solid_volume(m) == doctest::Approx(exact).epsilon(1e-5));
}

TEST_CASE("valve leaflets: a free-edge rise lifts the free edge's middle, not its ends") {
  valve::ValveGeometry g;
  g.free_edge_rise = 3e-3;
  valve::validate(g);
  const structure::SolidMesh m = valve::valve_leaflets(g);
  // z = z_free + rise (1 - q^2), q the position across the leaflet in [-1, 1] (q = 0 at the
  // leaflet centre, +-1 at the posts): nodes on the free edge follow the parabola exactly.
  double highest = 0, lowest = INFINITY;
  for (int n : m.node_set("free_edge")) {
    const double th = std::atan2(m.X(1, n), m.X(0, n));
    double q = INFINITY;
    for (int k = 0; k < 3; ++k)
      q = std::min(q, std::abs(std::remainder(th - g.leaflet_centre_angle(k), 2 * M_PI)));
    q /= g.leaflet_span() / 2;
    CHECK(m.X(2, n) == doctest::Approx(g.free_edge_z() + g.free_edge_rise * (1 - q * q)));
    highest = std::max(highest, m.X(2, n)), lowest = std::min(lowest, m.X(2, n));
  }
  CHECK(highest == doctest::Approx(g.free_edge_z() + g.free_edge_rise));
  CHECK(lowest == doctest::Approx(g.free_edge_z()));
  // The attachment does not move: the same nodes on the scallop and on the posts.
  const valve::ValveGeometry flat;
  const structure::SolidMesh m0 = valve::valve_leaflets(flat);
  for (int n : m.node_set("attachment")) CHECK((m.X.col(n) - m0.X.col(n)).norm() < 1e-15);
  g.free_edge_rise = -1e-3;
  CHECK_THROWS_WITH_AS(valve::validate(g), doctest::Contains("free_edge_rise"),
                       std::invalid_argument);
}

TEST_CASE("leaflets.msh: written through the Gmsh API, read back by read_solid_gmsh") {
  const std::filesystem::path dir = "test_output/valve_leaflets";
  std::filesystem::create_directories(dir);
  valve::ValveGeometry g;
  g.mesh_size = 3e-3;
  const structure::SolidMesh m = valve::valve_leaflets(g);
  valve::write_leaflets_gmsh(dir / "leaflets.msh", m);
  const structure::SolidMesh r = valve::read_valve_leaflets(dir / "leaflets.msh");
  REQUIRE(r.num_nodes() == m.num_nodes());
  REQUIRE(r.num_elements() == 3 * 5 * 3);
  CHECK((r.X - m.X).cwiseAbs().maxCoeff() < 1e-15);
  CHECK(r.connectivity == m.connectivity);
  for (const auto& [name, nodes] : m.node_sets) {
    if (name.size() == 2) continue;  // block sides u0..w1 are not written
    CAPTURE(name);
    REQUIRE(r.node_sets.count(name));
    CHECK(r.node_set(name) == nodes);
  }
  for (const char* set : kSets) CHECK(r.surface_set(set).size() == m.surface_set(set).size());
  // The faces read back are the faces written (element, local face).
  auto key = [](std::vector<structure::FaceRef> f) {
    std::vector<int> k;
    for (auto x : f) k.push_back(6 * x.element + x.face);
    std::sort(k.begin(), k.end());
    return k;
  };
  CHECK(key(r.surface_set("leaflet2_aortic_face")) == key(m.surface_set("leaflet2_aortic_face")));

  const structure::SolidMesh one = valve::leaflet_submesh(r, 2);
  CHECK(one.num_elements() == 15);
  CHECK(one.num_nodes() == r.num_nodes() / 3);
  CHECK(one.surface_set("aortic_face").size() == 15);
  CHECK(one.node_set("attachment").size() == r.node_set("leaflet2_attachment").size());
  CHECK_NOTHROW(one.validate());
  CHECK(solid_volume(one) == doctest::Approx(solid_volume(r) / 3).epsilon(1e-12));
}

TEST_CASE("leaflets.msh: a mesh without the valve groups is refused naming the group") {
  const std::filesystem::path dir = "test_output/valve_leaflets";
  std::filesystem::create_directories(dir);
  valve::ValveGeometry g;
  g.mesh_size = 3e-3;
  structure::SolidMesh m = valve::valve_leaflets(g);
  m.surface_sets["leaflet3_free_edge"].clear();
  valve::write_leaflets_gmsh(dir / "no_free_edge.msh", m);  // writes an empty group
  CHECK_THROWS_WITH_AS(valve::read_valve_leaflets(dir / "no_free_edge.msh"),
                       doctest::Contains("'leaflet3_free_edge' is missing or empty"),
                       mesh::MeshFileError);
}
