// Cylinder channel flow set-up; see cylinder_channel_flow.hpp.
#include "validation/dfg_cylinder/cylinder_channel_flow.hpp"

#include "flow/poisson_weights.hpp"

namespace valsalva::validation {

CylinderChannelFlow make_cylinder_channel_flow(const mesh::Mesh& mesh,
                                               const mesh::DualMetrics& metrics,
                                               const mesh::LocalMesh& local, double rho, double nu,
                                               flow::Waveform inflow, bool stiffness_viscous) {
  auto inlet = flow::boundary_spec("inlet", flow::BoundaryType::inlet);
  inlet.profile = flow::InletProfile::plane_poiseuille;
  inlet.across = Eigen::Vector3d(0, 1, 0);
  inlet.flow_rate = std::move(inflow);
  CylinderChannelFlow out;
  out.bc = std::make_shared<flow::BoundaryConditions>(
      local,
      std::vector<flow::BoundarySpec>{
          inlet, flow::boundary_spec("outlet", flow::BoundaryType::pressure_outlet),
          flow::boundary_spec("wall", flow::BoundaryType::wall),
          flow::boundary_spec("cylinder", flow::BoundaryType::wall)},
      nu);
  flow::ProjectionOptions options;
  options.density = rho;
  options.viscosity = nu;
  options.poisson.tolerance = 1e-10;
  options.stiffness_viscous = stiffness_viscous;
  options.boundary = out.bc;
  options.poisson.dirichlet = out.bc->pressure_dirichlet();
  // The P1 weights on tetrahedra, their extruded form on prisms (the slab of unsplit prisms).
  out.solver = std::make_unique<flow::ProjectionRK4>(
      local, options, flow::slab_stiffness_weights(mesh, metrics, local));
  return out;
}

void impose_initial_boundary_values(flow::BoundaryConditions& bc, flow::FlowState& state) {
  bc.impose_pressure(state.pressure);
  bc.hold_outlets(state.velocity);
  bc.impose(state.velocity, 0.0);
}

flow::WallForceInput cylinder_force_input(const mesh::LocalMesh& local,
                                          const flow::ProjectionRK4& solver,
                                          const flow::FlowState& state, double rho, double nu,
                                          flow::TensorField& grad,
                                          const flow::VectorField* body_force) {
  flow::gradient(local, state.velocity, grad);
  flow::WallForceInput in;
  in.density = rho;
  in.dynamic_viscosity = rho * nu;
  in.velocity = &state.velocity;
  in.pressure = &state.pressure;
  in.velocity_gradient = &grad;
  in.laplacian_weights = &solver.viscous_weights();
  in.stiffness_weights = !solver.viscous_correction();
  in.body_force = body_force;
  return in;
}

Eigen::Vector3d cylinder_force(const mesh::LocalMesh& local, const flow::ProjectionRK4& solver,
                               const flow::FlowState& state, double rho, double nu,
                               flow::TensorField& grad, const flow::VectorField* body_force) {
  return flow::wall_force(local, "cylinder",
                          cylinder_force_input(local, solver, state, rho, nu, grad, body_force));
}

}  // namespace valsalva::validation
