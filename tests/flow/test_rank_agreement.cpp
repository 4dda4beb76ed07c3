// Rank-count agreement (issue 3 item 6): a short Taylor-Green run on split tetrahedra (periodic;
// also with central4 + the 4th-order operators on perturbed tetrahedra)
// and a short Womersley pipe run (Gmsh tetrahedra, Womersley inlet, wall, pressure outlet with
// backflow stabilisation: validation/womersley/womersley_delaunay.toml with overrides, run by
// run::Simulation as users run it) give the same velocity and pressure on the communicator (np 1,
// 2, 3) as on one rank alone (MPI_COMM_SELF), node by node in the partition-independent dual-node
// order.
// Tolerance 1e-10 relative: the Poisson solves stop at a relative residual of 1e-13, so the
// rank-dependent parts left are the AMG hierarchy's effect on that residual (1e-13 relative per
// step) and round-off in the reductions (1e-16 per operation), summed over a few steps; a
// halo or ownership bug changes fields at O(1) of their size.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "field_test_utils.hpp"
#include "run/run_loop.hpp"
#include "validation/bench/womersley_run.hpp"

using namespace valsalva;

namespace {

constexpr double kTolerance = 1e-10;

double max_abs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

// Both fields (velocity, pressure) of one run by dual node.
struct Fields {
  std::vector<double> velocity, pressure;
};

void check_agreement(const Fields& on_comm, const Fields& alone, const std::string& what) {
  const double du = test::max_abs_difference(on_comm.velocity, alone.velocity);
  const double dp = test::max_abs_difference(on_comm.pressure, alone.pressure);
  const double u_scale = max_abs(alone.velocity), p_scale = max_abs(alone.pressure);
  MESSAGE(what << ": max |du| / max |u| " << du / u_scale << ", max |dp| / max |p| "
               << dp / p_scale);
  REQUIRE(u_scale > 0);
  REQUIRE(p_scale > 0);
  CHECK(du <= kTolerance * u_scale);
  CHECK(dp <= kTolerance * p_scale);
}

// order4: central4 with the 4th-order operators (their edge corrections read the first ghost
// layer's gradients), on tetrahedra perturbed by 20% of h.
Fields taylor_green(MPI_Comm comm, bool order4 = false) {
  auto spec = test::periodic_box("tetra", 12, order4 ? 0.2 : 0.0);
  spec.length = Eigen::Vector3d::Constant(2 * std::numbers::pi);
  const auto mesh = mesh::generate_box(spec);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, comm);
  scene::RunOptions o;
  o.projection.density = 1.0;
  o.projection.viscosity = 0.01;
  o.projection.poisson.tolerance = 1e-13;
  if (order4) {
    o.projection.scheme = flow::ConvectionKind::central4;
    o.projection.fourth_order_operators = true;
  }
  o.initial = {flow::InitialType::taylor_green, 1.0, 1.0};
  o.time.end = 1.0;
  o.time.max_steps = 6;
  o.output.print = false;
  run::RunLoop loop(mesh, metrics, local, o);
  loop.run();
  std::vector<double> u;
  for (const auto& v : loop.state().velocity) u.insert(u.end(), {v.x(), v.y(), v.z()});
  const auto n = static_cast<mesh::GlobalIndex>(metrics.num_nodes());
  return {test::gather_by_dual_node(local, u, 3, n),
          test::gather_by_dual_node(local, loop.state().pressure, 1, n)};
}

Fields womersley(MPI_Comm comm) {
  validation::WomersleySetup s;
  s.womersley = 4;
  s.nodes_per_diameter = 6;
  s.poisson_tolerance = 1e-13;
  s.max_steps = 8;
  const auto r = validation::run_womersley(s, comm);
  return {r.final_velocity, r.final_pressure};
}

}  // namespace

TEST_CASE("a short Taylor-Green run gives the same fields at any rank count") {
  check_agreement(taylor_green(MPI_COMM_WORLD), taylor_green(MPI_COMM_SELF), "Taylor-Green");
  check_agreement(taylor_green(MPI_COMM_WORLD, true), taylor_green(MPI_COMM_SELF, true),
                  "Taylor-Green, central4 + 4th-order operators, perturbed tetrahedra");
}

TEST_CASE("a short Womersley pipe run gives the same fields at any rank count") {
  check_agreement(womersley(MPI_COMM_WORLD), womersley(MPI_COMM_SELF), "Womersley pipe");
}
