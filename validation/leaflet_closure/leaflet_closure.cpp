// Leaflet closure: the manufactured (open) leaflet is a 120-degree patch of a cylinder of radius
// 12.5 mm (the aortic root), 0.15 mm thick, quasi-incompressible neo-Hookean G = 2.4 MPa,
// K = 1.6 MPa, clamped along its attachment arc (z = 0) and closed by a uniform follower pressure
// on its outer (aortic) face, applied in load steps as in the reference study. The closed
// geometry is written for later use as the unstressed initial leaflet.
// Metrics: the solve converges to the full pressure; final equilibrium residual.
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <fmt/os.h>

#include "structure/mesh_generators.hpp"
#include "structure/static_solver.hpp"
#include "validation/case.hpp"
#include "validation/leaflet_closure/leaflet_closure.hpp"

namespace valsalva::validation {

using namespace valsalva::structure;

LeafletClosure close_leaflet(bool fine, double pressure, bool verbose) {
  ShellPatch sp;  // R 12.5 mm, 120 degrees, t 0.15 mm
  sp.height = 10e-3;
  sp.n_angle = fine ? 32 : 16;  // 512 / 128 Q2 elements: the reference study's 1536 / 384 for 3
  sp.n_height = fine ? 16 : 8;
  sp.n_thickness = 1;
  LeafletClosure c;
  c.mesh = cylindrical_shell_patch(HexOrder::q2, sp);
  c.radius = sp.radius;
  const auto mat = make_neo_hookean(2.4e6, 1.6e6);
  SolidForces forces(c.mesh, *mat);
  StaticProblem prob;
  prob.forces = &forces;
  prob.dirichlet.push_back({c.mesh.node_set("attachment"), {true, true, true}, {}});
  prob.pressures.push_back({c.mesh.surface_set("outer"), pressure});
  NewtonOptions o;
  o.load_steps = 10;
  o.damping = 1e-3;
  // Thin 3D shell: K's condition number ~ (L/t)^4 puts the round-off floor of the residual,
  // relative to the small pressure load, near 1e-7.
  o.rtol = 1e-6;  // pseudo-transient continuation through the shell's limit points
  o.verbose = verbose;
  const auto t0 = std::chrono::steady_clock::now();
  c.result = solve_static(prob, o);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c;
}

namespace {

void write_geometry(const LeafletClosure& c, const std::filesystem::path& dir) {
  auto nodes = fmt::output_file((dir / "closed_leaflet_nodes.csv").string());
  nodes.print("node,X,Y,Z,x,y,z\n");
  for (int n = 0; n < c.mesh.num_nodes(); ++n)
    nodes.print("{},{:.10e},{:.10e},{:.10e},{:.10e},{:.10e},{:.10e}\n", n, c.mesh.X(0, n), c.mesh.X(1, n),
                c.mesh.X(2, n), c.result.x(0, n), c.result.x(1, n), c.result.x(2, n));
  auto cells = fmt::output_file((dir / "closed_leaflet_hex27.csv").string());
  cells.print("# Q2 hexahedra, 27 nodes each in Gmsh order, 0-based node ids\n");
  const int nen = c.mesh.nodes_per_element();
  for (int e = 0; e < c.mesh.num_elements(); ++e) {
    for (int a = 0; a < nen; ++a) cells.print("{}{}", c.mesh.element_nodes(e)[a], a + 1 < nen ? "," : "\n");
  }
}

void run(const Context& ctx, Report& report) {
  const double pressure = 40.0;  // [Pa]
  const LeafletClosure c = close_leaflet(!ctx.quick, pressure, false);
  report.add("Newton converged to full pressure (1 = yes)", c.result.converged ? 1.0 : 0.0, 1.0, 0.0);
  report.add("final relative residual", c.result.last_residuals.empty() ? INFINITY : c.result.last_residuals.back(),
             0.0, 1e-6, Check::at_most);
  // Free-edge midpoint on the mid-surface: angle 0, z = height, radius R.
  int mid = -1;
  for (int n : c.mesh.node_set("free_edge"))
    if (std::abs(c.mesh.X(1, n)) < 1e-12 && std::abs(c.mesh.X(0, n) - c.radius) < 1e-9) mid = n;
  const double r_mid = std::hypot(c.result.x(0, mid), c.result.x(1, mid));
  // Not yet a metric: with only the attachment arc clamped, 40 Pa flattens the arc and the
  // free-edge midpoint moves slightly outward (see solve.csv); the closed-shape criterion needs
  // the commissural supports and a larger pressure, left to the follow-up issue.
  write_geometry(c, ctx.out_dir);
  auto s = fmt::output_file((ctx.out_dir / "solve.csv").string());
  s.print("elements,pressure_Pa,converged,load_steps,newton_iterations,cuts,seconds,solver,free_edge_mid_radius_m\n");
  s.print("{},{},{},{},{},{},{:.3f},{},{:.6e}\n", c.mesh.num_elements(), pressure, c.result.converged,
          c.result.steps, c.result.iterations, c.result.cuts, c.seconds, c.result.solver, r_mid);
  if (!c.result.converged) fmt::print(stderr, "leaflet_closure: {}\n", c.result.diagnosis);
}

}  // namespace

Case leaflet_closure_case() {
  return {"leaflet_closure",
          "Cylindrical leaflet (R 12.5 mm, t 0.15 mm) clamped on its attachment arc, closed by pressure", run};
}

}  // namespace valsalva::validation
