// End-of-run wall evaluations of the DFG cylinder; see wall_diagnostics.hpp.
#include "validation/dfg_cylinder/wall_diagnostics.hpp"

#include "analysis/probes.hpp"
#include "validation/dfg_cylinder/cylinder_channel_flow.hpp"

namespace valsalva::validation {

EndDiagnostics end_diagnostics(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                               const mesh::LocalMesh& local, const flow::ProjectionRK4& solver,
                               const flow::FlowState& state, double yc, double zc, double delta,
                               double q, const CylinderFluid& fluid) {
  EndDiagnostics d;
  flow::TensorField grad;
  auto in = cylinder_force_input(local, solver, state, fluid.rho, fluid.nu, grad);
  const Eigen::Vector3d full = flow::wall_force(local, "cylinder", in);
  const flow::ScalarField zero(state.pressure.size(), 0.0);
  in.pressure = &zero;
  const Eigen::Vector3d no_p = flow::wall_force(local, "cylinder", in);
  in.pressure = &state.pressure;
  in.dynamic_viscosity = 0;
  const Eigen::Vector3d no_mu = flow::wall_force(local, "cylinder", in);
  const Eigen::Vector3d surface_p =
      flow::wall_force(local, "cylinder", in, flow::WallForceMethod::surface);
  in.dynamic_viscosity = fluid.rho * fluid.nu;
  d.cl_pressure = (full - no_p).y() / q;
  d.cl_viscous = (full - no_mu).y() / q;
  d.cl_convective = full.y() / q - d.cl_pressure - d.cl_viscous;
  d.cl_surface_pressure = surface_p.y() / q;
  const auto loads = flow::wall_loads(local, "cylinder", in);
  std::tie(d.p_front, d.p_back) =
      StagnationTraction(mesh, 0.2, yc, 0.5 * fluid.diameter).pressures(local, loads);
  std::vector<analysis::ProbePoint> points;
  for (int k = 0; k <= 3; ++k) {
    points.push_back({"front", Eigen::Vector3d(0.15 - k * delta, yc, zc)});
    points.push_back({"back", Eigen::Vector3d(0.25 + k * delta, yc, zc)});
  }
  const auto v = analysis::Probes(mesh, metrics, local, points).sample(state);
  auto p = [&](int k, int side) { return v[4 * (2 * k + side) + 3]; };
  d.p_front_wall_node = p(0, 0), d.p_back_wall_node = p(0, 1);
  d.p_front_linear = 2 * p(1, 0) - p(2, 0), d.p_back_linear = 2 * p(1, 1) - p(2, 1);
  d.p_front_quadratic = 3 * p(1, 0) - 3 * p(2, 0) + p(3, 0);
  d.p_back_quadratic = 3 * p(1, 1) - 3 * p(2, 1) + p(3, 1);
  return d;
}

}  // namespace valsalva::validation
