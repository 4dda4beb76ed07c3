// Issue 4, verification 5: an LES run gives the same result at 1, 2 and 3 ranks. Taylor-Green
// vortex Re 1600 on 16^3 hexahedra, central4 + sigma, 6 steps at CFL 0.5, for both nu_sgs update
// policies; velocity and nu_sgs at every node against the same run on one rank (each rank runs
// it alone on MPI_COMM_SELF).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "../flow/field_test_utils.hpp"
#include "flow/poisson_weights.hpp"
#include "flow/projection_rk4.hpp"
#include "les/subgrid_viscosity.hpp"
#include "validation/tgv_les/tgv_les_run.hpp"

using namespace valsalva;

namespace {

struct LesRun {
  flow::VectorField velocity;
  flow::ScalarField nu_sgs;
  double max_nu_sgs = 0;
};

LesRun run(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics, const mesh::LocalMesh& local,
           les::SgsUpdate update) {
  const les::SubgridViscosity sgs(les::SgsKind::sigma, {}, local.h, update);
  flow::ProjectionOptions o;
  o.density = 1;
  o.viscosity = 1.0 / 1600;
  o.scheme = flow::ConvectionKind::central4;
  // Rank agreement to 1e-10 needs a projection converged far below it (as in test_run_loop).
  o.poisson.tolerance = 1e-13;
  o.subgrid_viscosity = [&](int stage, const flow::TensorField& g, flow::ScalarField& nu) {
    sgs(stage, g, nu);
  };
  flow::ProjectionRK4 solver(local, o, flow::poisson_weights(mesh, metrics, local));
  auto state = validation::tgv_re1600_initial_state(local);
  const double dt = 0.5 * 2 * std::numbers::pi / 16;
  for (int s = 0; s < 6; ++s) solver.step(state, dt);
  return {state.velocity, solver.subgrid_viscosity(), solver.max_subgrid_viscosity()};
}

}  // namespace

TEST_CASE("LES (TGV Re 1600, central4, sigma) agrees with the serial run to 1e-10") {
  mesh::BoxSpec box;
  box.cells = {16, 16, 16};
  box.length = Eigen::Vector3d::Constant(2 * std::numbers::pi);
  box.periodic = {true, true, true};
  const auto mesh = mesh::generate_box(box);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  const auto serial = mesh::distribute(mesh, metrics, MPI_COMM_SELF);
  const auto n = static_cast<mesh::GlobalIndex>(metrics.num_nodes());
  for (const auto update : {les::SgsUpdate::step, les::SgsUpdate::stage}) {
    const auto a = run(mesh, metrics, local, update);
    const auto b = run(mesh, metrics, serial, update);
    const double du = test::max_abs_difference(
        test::gather_by_dual_node(local, test::flatten(a.velocity), 3, n),
        test::gather_by_dual_node(serial, test::flatten(b.velocity), 3, n));
    const double dnu = test::max_abs_difference(test::gather_by_dual_node(local, a.nu_sgs, 1, n),
                                                test::gather_by_dual_node(serial, b.nu_sgs, 1, n));
    MESSAGE("update " << les::to_string(update) << ", np " << local.comm.size()
                      << " vs serial: max |du| " << du << " (V0 = 1), max |d nu_sgs| / nu "
                      << dnu * 1600 << ", max nu_sgs / nu " << a.max_nu_sgs * 1600);
    // The model must be active for the comparison to mean anything (measured max nu_sgs / nu 21
    // after 6 steps).
    CHECK(a.max_nu_sgs * 1600 > 0.1);
    CHECK(du < 1e-10);          // issue 4: 1e-10 (velocity scale V0 = 1)
    CHECK(dnu * 1600 < 1e-10);  // nu_sgs relative to nu
  }
}
