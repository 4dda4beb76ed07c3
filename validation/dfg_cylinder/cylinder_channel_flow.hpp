// The flow of the DFG / Turek–Hron cylinder channel on an io/cylinder_channel_generator slab:
// plane-Poiseuille inlet carrying Q(t), pressure outlet (p = 0, do-nothing-like), no-slip
// channel walls and cylinder; the projection solver with P1 Poisson weights (their extruded
// form on a slab of prisms, flow::slab_stiffness_weights). Shared by the
// dfg_cylinder and turek_hron_fsi cases. `stiffness_viscous`: the viscous term with the P1
// weights of the Poisson matrix (flow::ProjectionOptions::stiffness_viscous; dfg_cylinder uses
// it, turek_hron_fsi keeps the default two-point + correction form it was measured with).
#pragma once

#include <memory>

#include "flow/boundary_conditions.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/wall_force.hpp"
#include "mesh/dual_metrics.hpp"

namespace valsalva::validation {

struct CylinderChannelFlow {
  std::shared_ptr<flow::BoundaryConditions> bc;
  std::unique_ptr<flow::ProjectionRK4> solver;
};

CylinderChannelFlow make_cylinder_channel_flow(const mesh::Mesh& mesh,
                                               const mesh::DualMetrics& metrics,
                                               const mesh::LocalMesh& local, double rho, double nu,
                                               flow::Waveform inflow,
                                               bool stiffness_viscous = false);

// Boundary values into `state` (sized to the local mesh) at t = 0.
void impose_initial_boundary_values(flow::BoundaryConditions& bc, flow::FlowState& state);

// The flow::wall_force input of `state` for the residual force with the solver's viscous
// weights; fills `grad` (the velocity gradient), whose lifetime the input borrows.
flow::WallForceInput cylinder_force_input(const mesh::LocalMesh& local,
                                          const flow::ProjectionRK4& solver,
                                          const flow::FlowState& state, double rho, double nu,
                                          flow::TensorField& grad,
                                          const flow::VectorField* body_force = nullptr);

// Force (N) of the fluid on the "cylinder" patch: the consistent residual force of
// flow/wall_force.hpp, with the body-force density in the wall-node balance when given.
// `grad` is scratch. Collective.
Eigen::Vector3d cylinder_force(const mesh::LocalMesh& local, const flow::ProjectionRK4& solver,
                               const flow::FlowState& state, double rho, double nu,
                               flow::TensorField& grad,
                               const flow::VectorField* body_force = nullptr);

}  // namespace valsalva::validation
