// The force of the fluid on the cylinder of the DFG / Turek-Hron channel (dfg_cylinder and
// turek_hron_fsi): the consistent residual force of flow/wall_force.hpp with the solver's
// viscous weights.
#pragma once

#include "flow/projection_rk4.hpp"
#include "flow/wall_force.hpp"
#include "mesh/dual_metrics.hpp"

namespace valsalva::validation {

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
