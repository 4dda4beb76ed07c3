// The cylinder force; see cylinder_channel_flow.hpp.
#include "validation/dfg_cylinder/cylinder_channel_flow.hpp"

namespace valsalva::validation {

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
