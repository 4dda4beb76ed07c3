// [structure.<name>] and [immersed] tables read into structures placed in the fluid: generator
// sizes, rotation then translation, clamped sets, material, the periodic box of the markers;
// and the errors that name the key.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/mesh_source.hpp"
#include "scene/scene_keys_structure.hpp"

using namespace valsalva;

namespace {

const std::string fluid = R"(
[mesh]
source = "box"
[mesh.box]
origin = [-0.01, 0.0, 0.002]
length = [0.04, 0.02, 0.006]
cells = [8, 4, 6]
periodic = ["z"]
[boundary.xmin]
type = "wall"
[boundary.xmax]
type = "wall"
[boundary.ymin]
type = "wall"
[boundary.ymax]
type = "wall"
)";

std::string error_of(const std::string& structure) {
  try {
    const auto scene = scene::parse_scene(fluid + structure, "t.toml");
    scene::read_immersed_setup(scene, scene::build_mesh(scene));
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "no error";
}

// A 1 x 4 x 3 element bar, the base of the error and contact cases.
const std::string bar = R"(
[structure.flap]
mesh = "bar"
size = [0.001, 0.008, 0.006]
elements = [1, 4, 3]
parameters = { G = 1.0e4, K = 1.0e5 }
)";

}  // namespace

TEST_CASE("a rotated and translated bar: node positions, sets, material and the periodic box") {
  const auto scene = scene::parse_scene(fluid + R"(
[immersed]
kernel = "roma3"
kernel_width = 3.0
coupling = "per_step"
dt_safety = 0.5
[structure.flap]
mesh = "bar"
origin = [0.0, 0.0, 0.0]
size = [0.001, 0.008, 0.006]
elements = [1, 4, 3]
rotation_axis = [0.0, 0.0, 2.0]
rotation_angle = 90.0
translate = [0.01, 0.0, 0.002]
material = "st_venant_kirchhoff"
parameters = { E = 1.4e6, nu = 0.4 }
clamped = ["bottom"]
tether_stiffness = 5.0
stresses = false
)",
                                        "t.toml");
  const auto setup = scene::read_immersed_setup(scene, scene::build_mesh(scene));
  REQUIRE(setup.structures.size() == 1);
  const auto& s = setup.structures[0];
  CHECK(s.name == "flap");
  CHECK_FALSE(s.stresses);
  CHECK(s.mesh.num_elements() == 12);
  CHECK(s.mesh.num_nodes() == 3 * 9 * 7);  // Q2: 2n + 1 nodes per direction
  // A quarter turn about +z maps (x, y, z) to (-y, x, z), then the translation.
  const auto& corner = s.mesh.X;
  const Eigen::Vector3d lo = corner.rowwise().minCoeff(), hi = corner.rowwise().maxCoeff();
  CHECK(lo.x() == doctest::Approx(0.01 - 0.008).epsilon(1e-12));
  CHECK(hi.x() == doctest::Approx(0.01).epsilon(1e-12));
  CHECK(lo.y() == doctest::Approx(0.0).scale(1e-3).epsilon(1e-12));
  CHECK(hi.y() == doctest::Approx(0.001).epsilon(1e-12));
  CHECK(lo.z() == doctest::Approx(0.002).epsilon(1e-12));
  CHECK(hi.z() == doctest::Approx(0.008).epsilon(1e-12));
  // The clamped set is the bar's y = 0 face, now at x = 0.01 after the rotation.
  CHECK(s.body.clamped_sets == std::vector<std::string>{"bottom"});
  for (int a : s.mesh.node_set("bottom"))
    CHECK(s.mesh.X(0, a) == doctest::Approx(0.01).epsilon(1e-12));
  CHECK(s.body.tether_stiffness == 5.0);
  CHECK(s.material != nullptr);
  const auto& o = setup.options;
  CHECK(o.transfer.kernel.type == ibm::KernelType::roma3);
  CHECK(o.transfer.kernel.width == 3.0);
  CHECK(o.mode == ibm::CouplingMode::per_step);
  CHECK(setup.dt_safety == 0.5);
  REQUIRE(o.box.has_value());
  CHECK(o.box->periodic == std::array{false, false, true});
  CHECK(o.box->length.z() == doctest::Approx(0.006));
  CHECK(o.box->origin.z() == doctest::Approx(0.002));
}

TEST_CASE("a scene without structure tables builds nothing") {
  const auto scene = scene::parse_scene(fluid, "t.toml");
  CHECK(scene::read_immersed_setup(scene, scene::build_mesh(scene)).empty());
}

TEST_CASE("bad structure tables name the key") {
  CHECK(error_of(bar + "clamped = [\"foot\"]\ntether_stiffness = 1.0\n")
            .find("key 'structure.flap.clamped': the mesh has no node set 'foot'") !=
        std::string::npos);
  CHECK(error_of(bar + "clamped = [\"bottom\"]\n")
            .find("key 'structure.flap.tether_stiffness': clamped node sets need a tether") !=
        std::string::npos);
  CHECK(error_of(bar + "rotation_axis = [0.0, 0.0, 0.0]\nrotation_angle = 10.0\n")
            .find("key 'structure.flap.rotation_axis': the rotation axis is zero") !=
        std::string::npos);
  CHECK(error_of(R"(
[structure.flap]
mesh = "bar"
size = [0.001, 0.008, 0.006]
elements = [1, 4, 3]
parameters = { G = 1.0e4 }
)")
            .find("material 'neo_hookean' needs parameter 'K'") != std::string::npos);
  CHECK(error_of(R"(
[structure.leaflet]
mesh = "shell_patch"
radius = 0.001
angle = 120.0
height = 0.01
thickness = 0.003
elements = [4, 4, 1]
parameters = { G = 1.0e4, K = 1.0e5 }
)")
            .find("key 'structure.leaflet.thickness': the shell is thicker than its diameter") !=
        std::string::npos);
  CHECK(error_of(R"(
[structure.a-b]
mesh = "bar"
size = [0.001, 0.008, 0.006]
elements = [1, 4, 3]
parameters = { G = 1.0e4, K = 1.0e5 }
)")
            .find("structure name 'a-b' is not a plain name") != std::string::npos);
}

TEST_CASE("contact keys: pairs of named surface sets, a wall, and the errors that name the key") {
  // A bar's bottom and top faces share no node, so they make a valid pair (as two leaflets of
  // one mesh would).
  const auto scene = scene::parse_scene(fluid + bar + R"(contact = ["bottom:top"]
contact_penalty = 50.0
contact_formulation = "two_half_pass"
contact_wall_radius = 0.02
contact_wall_faces = ["front"]
)",
                                        "t.toml");
  const auto setup = scene::read_immersed_setup(scene, scene::build_mesh(scene));
  const auto& body = setup.structures.at(0).body;
  const auto& mesh = setup.structures.at(0).mesh;
  REQUIRE(body.contact.size() == 1);
  CHECK(body.contact[0].a.size() == mesh.surface_set("bottom").size());
  CHECK(body.contact[0].b.size() == mesh.surface_set("top").size());
  CHECK(body.contact_options.penalty_factor == 50.0);
  CHECK(body.contact_options.formulation == structure::ContactOptions::Formulation::two_half_pass);
  REQUIRE(body.obstacles.size() == 1);
  CHECK(body.obstacles[0].radius == 0.02);
  CHECK(body.obstacles[0].faces.size() == mesh.surface_set("front").size());

  // '+' joins sets: top+back shares the edge z = 0 with bottom.
  CHECK(error_of(bar + "contact = [\"bottom:top+back\"]\n").find("lies on both surfaces") !=
        std::string::npos);
  CHECK(error_of(bar + "contact = [\"bottom:lid\"]\n")
            .find("key 'structure.flap.contact': the mesh has no surface set 'lid'") !=
        std::string::npos);
  CHECK(error_of(bar + "contact = [\"bottom\"]\n").find("is not of the form A:B") !=
        std::string::npos);
  CHECK(error_of(bar + "contact_wall_faces = [\"front\"]\n")
            .find("key 'structure.flap.contact_wall_radius'") != std::string::npos);
  CHECK(error_of(bar + "contact_wall_radius = 0.02\n")
            .find("key 'structure.flap.contact_wall_faces'") != std::string::npos);
}

TEST_CASE("a sphere shell released from a stretched shape: sets, radius, start positions") {
  const auto sphere = [](const std::string& elements) {
    return R"(
[structure.cell]
mesh = "sphere_shell"
radius = 0.002
thickness = 0.0004
translate = [0.01, 0.01, 0.005]
parameters = { G = 1.0e4, K = 1.0e5 }
elements = )" +
           elements + "\n";
  };
  const auto scene = scene::parse_scene(
      fluid + sphere("[2, 2, 1]") + "initial_stretch = [1.25, 1.0, 0.8]\n", "t.toml");
  const auto setup = scene::read_immersed_setup(scene, scene::build_mesh(scene));
  const auto& s = setup.structures.at(0);
  CHECK(s.mesh.num_elements() == 6 * 2 * 2);
  const Eigen::Vector3d centre(0.01, 0.01, 0.005);
  for (int a : s.mesh.node_set("inner"))
    CHECK((s.mesh.X.col(a) - centre).norm() == doctest::Approx(0.0018).epsilon(1e-12));
  for (int a : s.mesh.node_set("outer"))
    CHECK((s.mesh.X.col(a) - centre).norm() == doctest::Approx(0.0022).epsilon(1e-12));
  // The start: the placed mesh stretched about its centre; the mesh stays the reference.
  REQUIRE(s.initial.cols() == s.mesh.num_nodes());
  for (int a = 0; a < s.mesh.num_nodes(); ++a) {
    const Eigen::Vector3d d = s.mesh.X.col(a) - centre;
    CHECK((s.initial.col(a) - centre - Eigen::Vector3d(1.25, 1.0, 0.8).cwiseProduct(d)).norm() <
          1e-15);
  }
  // Without initial_stretch the markers start at the reference positions.
  const auto plain = scene::parse_scene(fluid + sphere("[2, 2, 1]"), "t.toml");
  CHECK(
      scene::read_immersed_setup(plain, scene::build_mesh(plain)).structures.at(0).initial.size() ==
      0);
  CHECK(error_of(sphere("[2, 3, 1]"))
            .find("key 'structure.cell.elements': a sphere shell has 2 x 3 elements") !=
        std::string::npos);
}

TEST_CASE("a bar glued to a cylinder (root_arc_radius) and bent at the start (initial_bend)") {
  // The bar 0.01 long, 0.002 high behind a cylinder of radius 0.003 about (0, 0.01).
  const auto glued = [](const std::string& radius) {
    return R"(
[structure.bar]
mesh = "bar"
origin = [0.0, 0.009, 0.002]
size = [0.01, 0.002, 0.006]
elements = [4, 1, 2]
parameters = { G = 1.0e4, K = 1.0e5 }
root_arc_centre = [0.0, 0.01, 0.0]
root_arc_radius = )" +
           radius + "\n";
  };
  const auto scene =
      scene::parse_scene(fluid + glued("0.003") + "initial_bend = 0.001\n", "t.toml");
  const auto setup = scene::read_immersed_setup(scene, scene::build_mesh(scene));
  const auto& m = setup.structures.at(0).mesh;
  // The clamped end on the arc, the tip where it was, the nodes between evenly spread.
  for (int a : m.node_set("u0"))
    CHECK(std::hypot(m.X(0, a), m.X(1, a) - 0.01) == doctest::Approx(0.003).epsilon(1e-12));
  for (int a : m.node_set("u1")) CHECK(m.X(0, a) == doctest::Approx(0.01).epsilon(1e-12));
  double root = 1e300;
  for (int a : m.node_set("u0")) root = std::min(root, m.X(0, a));
  CHECK(root == doctest::Approx(std::sqrt(0.003 * 0.003 - 0.001 * 0.001)).epsilon(1e-12));
  // The start: y bent by 0.001 s^2 from x_root to the tip, x and z as in the mesh.
  const auto& x = setup.structures.at(0).initial;
  REQUIRE(x.cols() == m.num_nodes());
  for (int a = 0; a < m.num_nodes(); ++a) {
    const double s = std::max(0.0, (m.X(0, a) - root) / (0.01 - root));
    CHECK(x(1, a) - m.X(1, a) == doctest::Approx(0.001 * s * s).epsilon(1e-12));
    CHECK(x(0, a) == m.X(0, a));
    CHECK(x(2, a) == m.X(2, a));
  }
  for (int a : m.node_set("u1"))
    CHECK(x(1, a) - m.X(1, a) == doctest::Approx(0.001).epsilon(1e-12));
  CHECK(error_of(glued("0.003")) == "no error");
  CHECK(
      error_of(glued("0.0009")).find("key 'structure.bar.root_arc_radius': the bar reaches y = ") !=
      std::string::npos);
  CHECK(error_of(glued("0.02")).find("key 'structure.bar.root_arc_radius': the arc reaches x = ") !=
        std::string::npos);
  CHECK(error_of(glued("0.003") + "initial_bend = 0.001\ninitial_stretch = [1.1, 1.0, 1.0]\n")
            .find("initial_bend and initial_stretch exclude each other") != std::string::npos);
}
