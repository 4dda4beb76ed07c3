// Section fluxes (analysis/section_flux.hpp) in a Poiseuille pipe (R 5 mm, 20 mm long, Gmsh
// tetrahedra of 1.5 mm, inlet Q = 2 mL/s): after a few steps from rest the projected face flux
// satisfies the discrete continuity equation at every node to the Poisson tolerance, so the flux
// through any complete cross-section equals the imposed (and discretely exact) inlet flow rate,
// although the flow is far from developed. Also: the sign follows the normal, RunAnalysis writes
// sections.csv, sections that cut nothing or have a zero normal are refused by name, and a plane
// across a periodic direction cuts the domain once.
#include <doctest/doctest.h>
#include <mpi.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/run_analysis.hpp"
#include "analysis/section_flux.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/periodic_pipe_generator.hpp"
#include "mesh/pipe_generator.hpp"
#include "run/run_loop.hpp"

using namespace valsalva;

namespace {

constexpr double radius = 0.005, length = 0.02, q_in = 2e-6;

analysis::SectionOptions section(std::string name, double z, Eigen::Vector3d normal = {0, 0, 1}) {
  analysis::SectionOptions o;
  o.name = std::move(name);
  o.point = {0, 0, z};
  o.normal = normal;
  return o;
}

}  // namespace

TEST_CASE("section flux of a Poiseuille pipe equals the inlet flow rate") {
  const auto mesh = mesh::generate_pipe_mesh(radius, length, 0.0015);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  scene::RunOptions options;
  options.projection.density = 1000;
  options.projection.viscosity = 1e-4;
  options.projection.poisson.tolerance = 1e-12;
  options.time.end = 1;
  options.time.max_steps = 5;
  options.output.print = false;
  auto inlet = flow::boundary_spec("inlet", flow::BoundaryType::inlet);
  inlet.profile = flow::InletProfile::poiseuille;
  inlet.flow_rate.mean = q_in;
  options.boundary = {inlet, flow::boundary_spec("outlet", flow::BoundaryType::pressure_outlet),
                      flow::boundary_spec("wall", flow::BoundaryType::wall)};
  run::RunLoop loop(mesh, metrics, local, options);
  loop.run();
  REQUIRE(loop.face_flux().size() == local.edges.size());

  // Planes through nodes of the mesh or between them, a disc wider than the pipe, and a tilted
  // plane (its cut is longer; the flux is the same).
  auto disc = section("disc", 0.0153);
  disc.bound = analysis::SectionOptions::Bound::disc;
  disc.radius = 1.2 * radius;
  auto box = section("box", 0.012);
  box.bound = analysis::SectionOptions::Bound::box;
  box.lo = {-0.01, -0.01, 0.0};
  box.hi = {0.01, 0.01, 0.02};
  std::vector<analysis::SectionOptions> cuts = {section("near_inlet", 0.002), section("mid", 0.01),
                                                disc, box,
                                                section("tilted", 0.01, {0.3, -0.2, 1.0})};
  for (const auto& o : cuts) {
    const analysis::SectionFlux s(local, o);
    const double q = s.flux(loop.face_flux());
    MESSAGE(o.name << ": " << s.edges() << " edges, Q = " << q << " m3/s, Q/Q_in - 1 = "
                   << q / q_in - 1 << ", projected dual area " << s.projected_area() << " m2");
    // What is left is the continuity residual summed over the nodes behind the cut, of the
    // order of the Poisson tolerance (1e-12, relative) times Q.
    CHECK(q == doctest::Approx(q_in).epsilon(1e-12));
    CHECK(s.edges() > 50);
  }
  const analysis::SectionFlux reversed(local, section("reversed", 0.01, {0, 0, -2}));
  CHECK(reversed.flux(loop.face_flux()) == doctest::Approx(-q_in).epsilon(1e-12));

  // Through RunAnalysis: sections.csv with one column per section.
  const auto dir = std::filesystem::path("section_flux_test_np") +=
      std::to_string(local.comm.size());
  if (local.comm.root()) std::filesystem::create_directories(dir);
  local.comm.barrier();
  analysis::AnalysisOptions a;
  a.sections.sections = {section("mid", 0.01), disc};
  {
    analysis::RunAnalysis analysis(mesh, metrics, local, a, 1000, 0.1, dir, false);
    analysis.sample(loop.state(), 5, loop.face_flux());
    analysis.finish();
  }
  local.comm.barrier();
  if (local.comm.root()) {
    std::ifstream in(dir / "sections.csv");
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    CHECK(header == "time,mid_flux,disc_flux");
    double t, q1, q2;
    char c;
    std::istringstream(row) >> t >> c >> q1 >> c >> q2;
    CHECK(t == loop.state().time);
    CHECK(q1 == doctest::Approx(q_in).epsilon(1e-12));
    CHECK(q2 == doctest::Approx(q_in).epsilon(1e-12));
  }
}

TEST_CASE("sections that cut nothing or have no normal are refused by name") {
  const auto mesh = mesh::generate_pipe_mesh(radius, length, 0.0025);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  CHECK_THROWS_WITH(analysis::SectionFlux(local, section("beyond", 0.05)),
                    doctest::Contains("section.beyond: the plane through (0, 0, 0.05) m"));
  auto aside = section("aside", 0.01);
  aside.point = {0.02, 0, 0.01};
  aside.bound = analysis::SectionOptions::Bound::disc;
  aside.radius = 0.003;
  CHECK_THROWS_WITH(analysis::SectionFlux(local, aside),
                    doctest::Contains("section.aside: the plane through (0.02, 0, 0.01) m with "
                                      "normal (0, 0, 1) cuts no mesh edge within its bound"));
  CHECK_THROWS_WITH(analysis::SectionFlux(local, section("flat", 0.01, {0, 0, 0})),
                    doctest::Contains("section.flat.normal: the normal is zero"));
}

TEST_CASE("a section across a periodic direction cuts the domain once") {
  // A box periodic in x, y and z (1 m^3, perturbed tetrahedra) with the uniform flow u = e_x: the
  // flux through the plane x = 0.55 is the box's section, 1 m^3/s. The edges across the periodic
  // pair join nodes whose stored positions are a period apart; taken at face value they would
  // count as cut by every plane between them, with the opposite sign (the flux was ~0).
  mesh::BoxSpec spec;
  spec.cell_type = mesh::BoxCellType::tetra;
  spec.cells = {5, 4, 3};
  spec.perturbation = 0.1;
  spec.periodic = {true, true, true};
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  flow::VectorField u(local.num_local(), Eigen::Vector3d::UnitX());
  flow::EdgeField flux;
  flow::central_face_flux(local, u, flux);
  for (double x : {0.05, 0.55, 0.95}) {
    analysis::SectionOptions o;
    o.name = "across";
    o.point = {x, 0.5, 0.5};
    o.normal = {1, 0, 0};
    const analysis::SectionFlux cut(local, o);
    INFO("x = " << x);
    CHECK(cut.flux(flux) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(cut.projected_area() == doctest::Approx(1.0).epsilon(1e-12));
  }
}

TEST_CASE("a section of a periodic pipe: edges through the periodic pair are not cut") {
  // Before the fix the edges from the last layer to the images of the first (stored at z = 0)
  // counted as cut by any plane between them, reversed: the projected area summed to zero.
  mesh::PeriodicPipeSpec spec;
  spec.radius = 0.002, spec.length = 0.00075, spec.target_size = 0.00025;
  const auto mesh = mesh::generate_periodic_pipe_mesh(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  double volume = 0;
  for (int i = 0; i < local.num_owned; ++i) volume += local.volume[i];
  const double cross_section = local.comm.sum(volume) / spec.length;  // the polygon's area
  for (double z : {0.000375, 0.0006, 0.0007}) {
    CAPTURE(z);
    const analysis::SectionFlux s(local, section("mid", z));
    CHECK(s.projected_area() == doctest::Approx(cross_section).epsilon(1e-12));
  }
}
