// Scene keys of the immersed structures ([immersed], [structure.<name>]; ibm/, structure/) and
// their reader.
#include "scene/scene_keys_structure.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <numbers>
#include <regex>

#include "io/solid_gmsh_reader.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_keys_bar_shape.hpp"
#include "structure/contact.hpp"
#include "structure/mesh_generators.hpp"
#include "structure/sphere_shell.hpp"

namespace valsalva::scene {

void declare_structure_keys(Schema& s) {
  s.section("immersed",
            "How immersed structures exchange forces and velocities with the fluid (used only "
            "when the scene has [structure.<name>] tables).");
  s.choice("immersed.kernel", {"peskin4", "roma3", "bspline3"})
      .def("peskin4")
      .unit_of("-")
      .doc(
          "Base kernel of the discrete Dirac delta, RKPM-corrected on the mesh so that it keeps "
          "partition of unity and zero first moments (ibm/kernels.hpp, ibm/rkpm.hpp)");
  s.real("immersed.kernel_width")
      .def(4.0)
      .above(0)
      .unit_of("h")
      .doc("Support width of the kernel in units of the local fluid mesh size");
  s.real("immersed.kernel_min_size")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc(
          "Floor of the mesh size h the kernel width is measured in: h = max(h of the node "
          "nearest the marker, this); 0 = the local mesh size. Small cells that the geometry "
          "forces (e.g. at a thin frame the leaflets are attached to) then do not shrink the "
          "kernel, whose stiffness bound on the time step falls as h^(3/2)");
  s.real("immersed.max_outside")
      .def(0.5)
      .at_least(0)
      .unit_of("h")
      .doc(
          "A marker farther than this beyond the fluid boundary (along the outward normal of "
          "the nearest boundary node in its support) stops the run naming the marker and the "
          "patch; the slack covers a curved wall's chord polygon and edges clamped on the wall");
  s.real("immersed.reuse_distance")
      .def(0.1)
      .at_least(0)
      .at_most(0.5)
      .unit_of("h")
      .doc(
          "A marker keeps its kernel support and RKPM-corrected weights until it has moved this "
          "far from where they were built (in units of the h they were built with); only the "
          "markers that moved farther are located again. 0 = every marker at every RK stage. "
          "The kernel lags its marker by less than this, which shifts interpolated velocities "
          "by at most this h |grad u|; spreading and interpolation stay adjoint");
  s.real("immersed.pressure_damping_in_support")
      .def(1.0)
      .at_least(0)
      .at_most(1)
      .unit_of("-")
      .doc(
          "Fraction of the flow step's pressure damping term (the Rhie-Chow face-flux correction "
          "dt/rho (avg(grad p) - grad p|_face) of flow/projection_rk4.hpp) kept in the "
          "tetrahedra (hexahedral meshes: edges) with a node in a marker's kernel support and "
          "none on the boundary. Across the pressure jump a loaded structure holds, that term is "
          "a face flux through the structure proportional to dt: under 93 mmHg the closed "
          "coarse valve leaks 16.6 mL/s with 1 (all of it, the default) and 8.3 mL/s with 0. "
          "Below 1 the term is split by whole tetrahedra, which keeps it stable on P1 weights "
          "(flow/damping_cells.hpp); cells with a node on the boundary keep "
          "immersed.pressure_damping_in_support_at_boundary of it (docs/valve.md, \"The "
          "pressure damping and the immersed jump\")");
  s.real("immersed.pressure_damping_in_support_at_boundary")
      .def(1.0)
      .at_least(0)
      .at_most(1)
      .unit_of("-")
      .doc(
          "Fraction of the pressure damping term kept in the tetrahedra (hexahedral meshes: "
          "edges) with a node in a marker's kernel support and one on the boundary: where a "
          "leaflet's attachment meets the root wall and the frame, its jump leaks through these "
          "cells too. Some damping is needed there: with 0 the odd-even pressure mode walls "
          "excite diverged valve runs where opening leaflets neared the sinus wall; 0.1 ran. "
          "1 (the default) keeps all of it");
  s.choice("immersed.coupling", {"per_stage", "per_step", "implicit"})
      .def("per_stage")
      .unit_of("-")
      .doc(
          "per_stage: forces spread and markers moved at every RK stage (1.24x the stable time "
          "step of per_step for 4x the transfer cost); per_step: forces held over the step "
          "(ibm/immersed_structure.hpp); implicit: the force extrapolated to the end of the step "
          "is held, and the markers' displacement solves the backward-Euler linearisation "
          "(I + dt^2/rho Interp Spread K) dX = dt U (ibm/implicit_markers.hpp): no time-step "
          "bound of its own, so the flow's CFL and Fourier targets set dt (stiff leaflets)");
  s.integer("immersed.implicit_newton_iterations")
      .def(1)
      .at_least(1)
      .unit_of("-")
      .doc(
          "coupling = \"implicit\": at most this many Newton iterations of the marker solve on "
          "the solid force (K re-assembled at each iterate; 1: the linearisation at the start of "
          "the step alone), which widens the stable time step of strained leaflets "
          "(ibm/implicit_markers.hpp)");
  s.real("immersed.implicit_newton_tolerance")
      .def(1e-6)
      .above(0)
      .at_most(1)
      .unit_of("-")
      .doc(
          "Newton stops once its update is below this fraction of the step's marker "
          "displacement");
  s.real("immersed.dt_safety")
      .def(0.9)
      .in_range(0, 1)
      .unit_of("-")
      .doc(
          "Fraction of the coupling's time-step bound (largest eigenvalue of Interp Spread K, "
          "ibm/ib_stability.hpp) the run may use; the bound was 1.2-1.4x below the measured "
          "limit in tests/ibm/test_ib_stability");
  s.integer("immersed.stability_check_every")
      .def(50)
      .at_least(1)
      .unit_of("-")
      .doc(
          "Re-evaluate that bound every this many steps (the stiffness changes as the solids "
          "deform; one evaluation costs about 100 spread-interpolate pairs)");
  s.integer("immersed.log_every")
      .def(10)
      .at_least(1)
      .unit_of("-")
      .doc("A row of structures.csv (force on the fluid, tether reaction, speed) every N steps");

  const std::string k = "structure.<name>";
  s.section(k,
            "An immersed solid (thick membrane, leaflet, bar) of hexahedra whose nodes are markers "
            "in the fluid; its results go to structures/<name>.xmf at the field output interval.");
  s.choice(k + ".mesh", {"bar", "shell_patch", "sphere_shell", "gmsh"})
      .required()
      .unit_of("-")
      .doc(
          "bar: a straight block (origin, size, elements; node sets clamped, tip, bottom, top, "
          "back, front and u0..w1); shell_patch: a cylindrical shell patch about the z axis "
          "(node sets attachment, free_edge, side0, side1); sphere_shell: a closed spherical "
          "shell about the origin, a cubed sphere without poles (radius, thickness, elements; "
          "node and surface sets inner, outer; structure/sphere_shell.hpp); gmsh: a .msh file of "
          "hexahedra with physical groups as node sets (structure/mesh_generators.hpp, "
          "io/solid_gmsh_reader.hpp)");
  s.choice(k + ".order", {"q2", "q1"})
      .def("q2")
      .unit_of("-")
      .doc("Element order of the generated mesh (quadratic hexahedra by default)");
  s.when(k + ".order", k + ".mesh", {"bar", "shell_patch", "sphere_shell"});
  s.string(k + ".file").required().unit_of("-").doc("Gmsh mesh, relative to the scene file");
  s.when(k + ".file", k + ".mesh", {"gmsh"});
  s.real3(k + ".origin").def(std::array{0.0, 0.0, 0.0}).unit_of("m").doc("Corner of the bar");
  s.when(k + ".origin", k + ".mesh", {"bar"});
  s.real3(k + ".size").required().above(0).unit_of("m").doc("Extent of the bar along x, y, z");
  s.when(k + ".size", k + ".mesh", {"bar"});
  s.real(k + ".radius")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Mid-surface radius of the patch or the sphere");
  s.real(k + ".angle")
      .required()
      .in_range(0, 360)
      .unit_of("deg")
      .doc("Angular span, centred on +x");
  s.real(k + ".height").required().above(0).unit_of("m").doc("Extent along the patch axis z");
  s.real(k + ".thickness").required().above(0).unit_of("m").doc("Shell thickness");
  for (const char* key : {".angle", ".height"}) s.when(k + key, k + ".mesh", {"shell_patch"});
  for (const char* key : {".radius", ".thickness"})
    s.when(k + key, k + ".mesh", {"shell_patch", "sphere_shell"});
  s.int3(k + ".elements")
      .required()
      .at_least(1)
      .unit_of("-")
      .doc(
          "Elements along x, y, z (bar), along the arc, the height and the thickness (patch), or "
          "along each edge of the cube's faces (twice the same number) and through the thickness "
          "(sphere)");
  s.when(k + ".elements", k + ".mesh", {"bar", "shell_patch", "sphere_shell"});
  s.real3(k + ".rotation_axis")
      .def(std::array{0.0, 0.0, 1.0})
      .unit_of("-")
      .doc("Axis of a rotation of the mesh about the coordinate origin, before the translation");
  s.real(k + ".rotation_angle").def(0.0).unit_of("deg").doc("Angle of that rotation");
  s.real3(k + ".translate").def(std::array{0.0, 0.0, 0.0}).unit_of("m").doc("Translation");
  s.real3(k + ".initial_stretch")
      .def(std::array{1.0, 1.0, 1.0})
      .above(0)
      .unit_of("-")
      .doc(
          "The markers start from the placed mesh stretched by these factors along x, y, z about "
          "the mean of its nodes (a body released from a deformed shape; factors whose product is "
          "1 keep its volume); the mesh as placed stays the stress-free reference");
  declare_bar_shape_keys(s, k);
  s.choice(k + ".material", structure::material_law_names())
      .def("neo_hookean")
      .unit_of("-")
      .doc("Constitutive law (structure/material.hpp)");
  s.real_table(k + ".parameters")
      .required()
      .unit_of("Pa, -")
      .doc(
          "Material parameters: neo_hookean {G, K}, mooney_rivlin {C10, C01, C11, K}, hgo {mu, "
          "K, k1, k2, kappa, gamma}, st_venant_kirchhoff and linear_elastic {E, nu}");
  s.string_list(k + ".clamped")
      .def(std::vector<std::string>{})
      .unit_of("-")
      .doc("Node sets held at their reference positions (how: clamp)");
  s.choice(k + ".clamp", {"tether", "fixed"})
      .def("tether")
      .unit_of("-")
      .doc(
          "tether: each clamped node is pulled to its reference position by a spring "
          "(tether_stiffness) and stays a marker of the coupling (an edge clamped inside the "
          "fluid); fixed: clamped nodes are held exactly (Dirichlet) and are no markers, their "
          "elastic force carried by the support (an edge on a rigid wall, e.g. leaflets on a "
          "valve frame, where a marker would have no fluid around it; no tether in the time-step "
          "bound)");
  s.real(k + ".tether_stiffness")
      .def(0.0)
      .at_least(0)
      .unit_of("N/m")
      .doc(
          "Spring per clamped node; needed with clamped sets and clamp = tether. Stiffer holds "
          "better but lowers "
          "the stable time step (it enters the coupling's bound like the solid stiffness)");
  s.string_list(k + ".contact")
      .def(std::vector<std::string>{})
      .unit_of("-")
      .doc(
          "Frictionless contact pairs between surfaces of this structure that belong to different "
          "bodies (disjoint node sets, e.g. the leaflets of one valve mesh), each \"A:B\" with A "
          "and B surface sets, or several joined by '+' (\"leaflet1_aortic_face+leaflet1_"
          "ventricular_face:leaflet2_aortic_face+leaflet2_ventricular_face\"). Penalty on the "
          "normal gap at the faces' Gauss points, both sides as slave in turn (Sauer & De "
          "Lorenzis 2013; structure/contact.hpp); its tangent enters the time-step bound");
  s.real(k + ".contact_penalty")
      .def(100.0)
      .above(0)
      .unit_of("E/h")
      .doc(
          "Penalty factor c: eps = c E / h with E three times the material's small-strain shear "
          "modulus and h the mean face size of the pair; the penetration at pressure p is "
          "(p / E) h / c. Between surfaces c hardly moves the stable time step (equal and opposite "
          "forces at one point spread to almost nothing); against a rigid wall (contact_wall_*) "
          "larger c lowers it as sqrt(c)");
  s.choice(k + ".contact_formulation", {"two_pass", "two_half_pass"})
      .def("two_pass")
      .unit_of("-")
      .doc(
          "two_pass: each surface is slave in turn and its traction acts half on it and half, as "
          "the reaction, on the other surface, so the contact forces cancel exactly (no net force "
          "spread into the fluid); two_half_pass: the traction acts on the slave only, which "
          "passes the contact patch test but leaves a net force (measured up to 41 % of the "
          "contact "
          "force on deformed non-matching meshes, tests/ibm/test_immersed_contact)");
  s.real(k + ".contact_search")
      .def(1.0)
      .above(0)
      .unit_of("h")
      .doc("Only closest points within this distance (above or below a face) are in contact");
  s.real(k + ".contact_clearance")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc(
          "Distance the surfaces of a contact pair are held apart: the penalty acts on the gap "
          "minus this. An immersed boundary cannot separate surfaces closer than about one fluid "
          "cell (both interpolate the same velocity), so coapting leaflets that must reopen need "
          "about the fluid mesh size near the valve (docs/valve.md); the leaflets of "
          "`close-leaflets --contact-clearance` use the same value. 0: surfaces touch");
  s.real(k + ".contact_smoothing")
      .def(0.0)
      .at_least(0)
      .below(1)
      .unit_of("h")
      .doc(
          "Width of the C1 smoothing of the penalty near zero gap (a quadratic branch, "
          "Wriggers 2006 sect. 10.3), so that Newton and the coupling see a differentiable "
          "force where points enter contact; adds at most half this width of penetration; 0: "
          "the plain penalty");
  s.real(k + ".contact_wall_radius")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc(
          "Radius of a rigid cylindrical wall (e.g. the aortic root) that the contact_wall_faces "
          "must stay inside; 0: no wall");
  s.real3(k + ".contact_wall_point")
      .def(std::array{0.0, 0.0, 0.0})
      .unit_of("m")
      .doc("A point on the wall's axis");
  s.real3(k + ".contact_wall_axis")
      .def(std::array{0.0, 0.0, 1.0})
      .unit_of("-")
      .doc("Direction of the wall's axis");
  s.string_list(k + ".contact_wall_faces")
      .def(std::vector<std::string>{})
      .unit_of("-")
      .doc("Surface sets kept inside the wall (needed with contact_wall_radius > 0)");
  s.boolean(k + ".stresses")
      .def(true)
      .unit_of("-")
      .doc("Write nodal von Mises, principal and Cauchy stresses with the structure");
}

namespace {

Eigen::Vector3d vec(const Scene& scene, const std::string& key) {
  const auto a = scene.get<std::array<double, 3>>(key);
  return {a[0], a[1], a[2]};
}

structure::SolidMesh build_solid_mesh(const Scene& scene, const std::string& k) {
  const auto type = scene.get<std::string>(k + ".mesh");
  if (type == "gmsh") {
    try {
      return io::read_solid_gmsh(scene.path(k + ".file"));
    } catch (const std::exception& e) {
      throw scene.error(k + ".file", e.what());
    }
  }
  const auto order = scene.get<std::string>(k + ".order") == "q1" ? structure::HexOrder::q1
                                                                  : structure::HexOrder::q2;
  const auto n = scene.get<std::array<int, 3>>(k + ".elements");
  if (type == "bar") {
    structure::Bar b;
    b.origin = vec(scene, k + ".origin");
    const auto size = vec(scene, k + ".size");
    b.length = size.x();
    b.height = size.y();
    b.depth = size.z();
    b.n_length = n[0];
    b.n_height = n[1];
    b.n_depth = n[2];
    return structure::straight_bar(order, b);
  }
  // A shell: a sphere or a cylindrical patch, both of a radius and a thickness.
  const double radius = scene.get<double>(k + ".radius");
  const double thickness = scene.get<double>(k + ".thickness");
  if (!(thickness < 2 * radius))
    throw scene.error(k + ".thickness", "the shell is thicker than its diameter");
  if (type == "sphere_shell") {
    if (n[0] != n[1])
      throw scene.error(k + ".elements",
                        fmt::format("a sphere shell has {} x {} elements on each cube face: the "
                                    "first two numbers must be equal",
                                    n[0], n[1]));
    return structure::sphere_shell({Eigen::Vector3d::Zero(), radius, thickness, n[0], n[2]});
  }
  structure::ShellPatch p;
  p.radius = radius;
  p.angle = scene.get<double>(k + ".angle") * std::numbers::pi / 180;
  p.height = scene.get<double>(k + ".height");
  p.thickness = thickness;
  p.n_angle = n[0];
  p.n_height = n[1];
  p.n_thickness = n[2];
  return structure::cylindrical_shell_patch(order, p);
}

// Rotates and translates the mesh; returns the rotation.
Eigen::Matrix3d place(const Scene& scene, const std::string& k, structure::SolidMesh& mesh) {
  const auto axis = vec(scene, k + ".rotation_axis");
  const double angle = scene.get<double>(k + ".rotation_angle") * std::numbers::pi / 180;
  if (angle != 0 && !(axis.norm() > 0))
    throw scene.error(k + ".rotation_axis", "the rotation axis is zero");
  const Eigen::Matrix3d r = angle == 0
                                ? Eigen::Matrix3d::Identity()
                                : Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  mesh.X = (r * mesh.X).colwise() + vec(scene, k + ".translate");
  return r;
}

// The markers' start positions: the placed mesh stretched about the mean of its nodes.
Eigen::Matrix3Xd initial_positions(const Scene& scene, const std::string& k,
                                   const structure::SolidMesh& mesh) {
  const Eigen::Vector3d stretch = vec(scene, k + ".initial_stretch");
  if (stretch == Eigen::Vector3d::Ones()) return {};
  const Eigen::Vector3d centre = mesh.X.rowwise().mean();
  return (stretch.asDiagonal() * (mesh.X.colwise() - centre)).colwise() + centre;
}

// The markers' periodic box: the mesh's periodic links must be translations along the axes.
std::optional<ibm::PeriodicBox> periodic_box(const Scene& scene, const mesh::Mesh& mesh) {
  if (mesh.periodic.empty()) return std::nullopt;
  ibm::PeriodicBox box;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
  for (const auto& x : mesh.nodes) lo = lo.cwiseMin(x);
  box.origin = lo;
  for (const auto& link : mesh.periodic) {
    int d = 0;
    const double len = link.translation.cwiseAbs().maxCoeff(&d);
    if (link.translation.norm() > len * (1 + 1e-12))
      throw scene.error("mesh.periodic",
                        fmt::format("immersed structures need periodic directions along x, y or "
                                    "z; the link {} -> {} translates by ({}, {}, {})",
                                    link.master, link.slave, link.translation.x(),
                                    link.translation.y(), link.translation.z()));
    box.periodic[d] = true;
    box.length[d] = len;
  }
  return box;
}

// Faces of the surface sets named in `names` ('+'-joined), or a SceneError naming the key.
std::vector<structure::FaceRef> named_faces(const Scene& scene, const std::string& key,
                                            const structure::SolidMesh& mesh,
                                            const std::vector<std::string>& names) {
  for (const auto& n : names)
    if (!mesh.surface_sets.count(n)) {
      std::vector<std::string> known;
      for (const auto& [name, faces] : mesh.surface_sets) known.push_back(name);
      throw scene.error(key, fmt::format("the mesh has no surface set '{}'", n),
                        fmt::format("{}", fmt::join(known, ", ")));
    }
  return structure::contact_surface(mesh, names);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out(1);
  for (char c : s)
    if (c == sep)
      out.emplace_back();
    else
      out.back() += c;
  return out;
}

void read_contact(const Scene& scene, const std::string& k, const structure::SolidMesh& mesh,
                  ibm::BodySpec& body) {
  for (const auto& pair : scene.get<std::vector<std::string>>(k + ".contact")) {
    const auto sides = split(pair, ':');
    if (sides.size() != 2 || sides[0].empty() || sides[1].empty())
      throw scene.error(k + ".contact",
                        fmt::format("contact pair '{}' is not of the form A:B", pair),
                        "\"SET[+SET...]:SET[+SET...]\"");
    structure::ContactPair p{pair, named_faces(scene, k + ".contact", mesh, split(sides[0], '+')),
                             named_faces(scene, k + ".contact", mesh, split(sides[1], '+'))};
    body.contact.push_back(std::move(p));
  }
  body.contact_options.penalty_factor = scene.get<double>(k + ".contact_penalty");
  body.contact_options.search_factor = scene.get<double>(k + ".contact_search");
  body.contact_options.smoothing = scene.get<double>(k + ".contact_smoothing");
  body.contact_options.clearance = scene.get<double>(k + ".contact_clearance");
  body.contact_options.formulation =
      scene.get<std::string>(k + ".contact_formulation") == "two_half_pass"
          ? structure::ContactOptions::Formulation::two_half_pass
          : structure::ContactOptions::Formulation::two_pass;
  const double radius = scene.get<double>(k + ".contact_wall_radius");
  const auto wall = scene.get<std::vector<std::string>>(k + ".contact_wall_faces");
  if (radius > 0) {
    if (wall.empty())
      throw scene.error(k + ".contact_wall_faces",
                        "a contact wall (contact_wall_radius > 0) needs the surface sets it holds");
    const Eigen::Vector3d axis = vec(scene, k + ".contact_wall_axis");
    if (!(axis.norm() > 0)) throw scene.error(k + ".contact_wall_axis", "the axis is zero");
    structure::RigidObstacle o;
    o.name = "wall";
    o.shape = structure::RigidObstacle::Shape::cylinder;
    o.point = vec(scene, k + ".contact_wall_point");
    o.direction = axis.normalized();
    o.radius = radius;
    o.inside = true;
    o.faces = named_faces(scene, k + ".contact_wall_faces", mesh, wall);
    body.obstacles.push_back(std::move(o));
  } else if (!wall.empty()) {
    throw scene.error(k + ".contact_wall_radius",
                      "contact_wall_faces are given but the wall radius is 0");
  }
}

}  // namespace

ImmersedSetup read_immersed_setup(const Scene& scene, const mesh::Mesh& mesh) {
  ImmersedSetup out;
  const auto names = scene.names("structure");
  if (names.empty()) return out;
  auto& o = out.options;
  o.transfer.kernel.type = ibm::parse_kernel_type(scene.get<std::string>("immersed.kernel"));
  o.transfer.kernel.width = scene.get<double>("immersed.kernel_width");
  o.transfer.max_outside = scene.get<double>("immersed.max_outside");
  o.transfer.min_h = scene.get<double>("immersed.kernel_min_size");
  o.transfer.reuse_distance = scene.get<double>("immersed.reuse_distance");
  const auto coupling = scene.get<std::string>("immersed.coupling");
  o.mode = coupling == "per_step"   ? ibm::CouplingMode::per_step
           : coupling == "implicit" ? ibm::CouplingMode::implicit
                                    : ibm::CouplingMode::per_stage;
  o.implicit_newton_iterations = scene.get<int>("immersed.implicit_newton_iterations");
  o.implicit_newton_tolerance = scene.get<double>("immersed.implicit_newton_tolerance");
  o.fluid_density = scene.get<double>("flow.density");
  o.time_scheme = flow::parse_time_scheme(scene.get<std::string>("time.scheme"));
  o.box = periodic_box(scene, mesh);
  out.dt_safety = scene.get<double>("immersed.dt_safety");
  out.damping_in_support = scene.get<double>("immersed.pressure_damping_in_support");
  out.damping_in_support_at_boundary =
      scene.get<double>("immersed.pressure_damping_in_support_at_boundary");
  o.stability_safety = out.dt_safety;
  out.stability_check_every = scene.get<int>("immersed.stability_check_every");
  out.log_every = scene.get<int>("immersed.log_every");

  static const std::regex valid("[A-Za-z0-9_]+");
  for (const auto& name : names) {
    const std::string k = "structure." + name;
    if (!std::regex_match(name, valid))
      throw scene.error(k, fmt::format("structure name '{}' is not a plain name", name),
                        "[A-Za-z0-9_]+");
    StructureSetup st;
    st.name = name;
    st.mesh = build_solid_mesh(scene, k);
    Eigen::Matrix3Xd bend;
    if (scene.get<std::string>(k + ".mesh") == "bar") {
      conform_bar_root(scene, k, st.mesh);
      bend = bar_bend(scene, k, st.mesh);
    }
    const Eigen::Matrix3d rotation = place(scene, k, st.mesh);
    st.initial = initial_positions(scene, k, st.mesh);
    if (bend.size() > 0) st.initial = st.mesh.X + rotation * bend;
    const auto where = scene.location(k + ".parameters").str() + ": key '" + k + ".parameters'";
    const auto law = structure::parse_material_law(scene.get<std::string>(k + ".material"));
    try {
      st.material = structure::make_material(
          law, scene.get<std::map<std::string, double>>(k + ".parameters"), where);
    } catch (const std::invalid_argument& e) {
      throw SceneError({e.what()});
    }
    // Mooney-Rivlin's shear modulus is 2 (C10 + C01): each may be 0, not both (a solid that
    // resists no shear lets the leaflet fold through the flow).
    if (const auto p = scene.get<std::map<std::string, double>>(k + ".parameters");
        law == structure::MaterialLaw::mooney_rivlin && !(p.at("C10") + p.at("C01") > 0))
      throw scene.error(k + ".parameters",
                        fmt::format("material 'mooney_rivlin': the shear modulus 2 (C10 + C01) = "
                                    "{:g} Pa is not positive",
                                    2 * (p.at("C10") + p.at("C01"))),
                        "C10 + C01 > 0");
    st.body.name = name;
    st.body.clamped_sets = scene.get<std::vector<std::string>>(k + ".clamped");
    for (const auto& set : st.body.clamped_sets)
      if (!st.mesh.node_sets.count(set)) {
        std::vector<std::string> known;
        for (const auto& [n, nodes] : st.mesh.node_sets) known.push_back(n);
        throw scene.error(k + ".clamped", fmt::format("the mesh has no node set '{}'", set),
                          fmt::format("{}", fmt::join(known, ", ")));
      }
    st.body.tether_stiffness = scene.get<double>(k + ".tether_stiffness");
    st.body.clamp =
        scene.get<std::string>(k + ".clamp") == "fixed" ? ibm::Clamp::fixed : ibm::Clamp::tether;
    if (!st.body.clamped_sets.empty() && st.body.clamp == ibm::Clamp::tether &&
        !(st.body.tether_stiffness > 0))
      throw scene.error(k + ".tether_stiffness",
                        "clamped node sets need a tether stiffness > 0 (N/m per node)");
    read_contact(scene, k, st.mesh, st.body);
    try {  // checks the pairs (different bodies) now, naming the key
      structure::Contact(st.mesh, *st.material, st.body.contact, st.body.obstacles,
                         st.body.contact_options);
    } catch (const std::invalid_argument& e) {
      throw scene.error(k + ".contact", e.what());
    }
    st.stresses = scene.get<bool>(k + ".stresses");
    out.structures.push_back(std::move(st));
  }
  return out;
}

}  // namespace valsalva::scene
