// A periodic box of hexahedra with the flow solver and an immersed block: the set-up shared by
// the coupling and stability tests.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <memory>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/projection_rk4.hpp"
#include "ibm/immersed_structure.hpp"
#include "io/box_generator.hpp"
#include "structure/material.hpp"
#include "structure/mesh_generators.hpp"

namespace valsalva::test {

struct IbBoxSpec {
  int cells = 16;           // per side of the unit periodic box
  double density = 1.0;     // fluid, kg/m^3
  double viscosity = 0.01;  // kinematic, m^2/s
  double shear_modulus = 1.0;
  double side = 0.3;     // reference cube of the block, centred in the box
  int elements = 3;      // Q2 elements per block side
  double stretch = 1.2;  // initial isochoric stretch along x
  ibm::CouplingMode mode = ibm::CouplingMode::per_stage;
  MPI_Comm comm = MPI_COMM_WORLD;
};

struct IbBox {
  flow::Mesh mesh;
  flow::DualMetrics metrics;
  flow::LocalMesh local;
  structure::SolidMesh solid;
  std::unique_ptr<structure::Material> material;
  std::unique_ptr<flow::ProjectionRK4> flow;
  std::unique_ptr<ibm::ImmersedStructure> ib;
  flow::FlowState state;

  explicit IbBox(const IbBoxSpec& s) {
    io::BoxSpec box;
    box.cells = {s.cells, s.cells, s.cells};
    box.periodic = {true, true, true};
    mesh = io::generate_box(box);
    metrics = flow::compute_dual_metrics(mesh);
    local = flow::distribute(mesh, metrics, s.comm, {4, "metis"});
    const Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.5 - s.side / 2);
    solid =
        structure::structured_block(structure::HexOrder::q2, {s.elements, s.elements, s.elements},
                                    [&](const structure::Vec3& u) { return lo + s.side * u; });
    material = structure::make_neo_hookean(s.shear_modulus, 10 * s.shear_modulus);
    flow::ProjectionOptions fluid;
    fluid.density = s.density;
    fluid.viscosity = s.viscosity;
    flow = std::make_unique<flow::ProjectionRK4>(local, fluid);
    ibm::ImmersedOptions options;
    options.mode = s.mode;
    options.fluid_density = s.density;
    options.box = ibm::PeriodicBox{};
    options.box->periodic = {true, true, true};
    ib = std::make_unique<ibm::ImmersedStructure>(local, options);
    ib->add_body(solid, *material, {"block", {}, 0});
    // Isochoric stretch about the box centre as the initial marker positions.
    const Eigen::Vector3d scale(s.stretch, 1 / std::sqrt(s.stretch), 1 / std::sqrt(s.stretch));
    Eigen::Matrix3Xd x = solid.X;
    for (int a = 0; a < x.cols(); ++a)
      x.col(a) = Eigen::Vector3d::Constant(0.5) +
                 scale.cwiseProduct(x.col(a) - Eigen::Vector3d::Constant(0.5));
    ib->set_positions(x);
    flow->set_body_force(ib->body_force());
    state = {flow::VectorField(local.num_local(), Eigen::Vector3d::Zero()),
             flow::ScalarField(local.num_local(), 0.0), 0.0};
  }

  void step(double dt) {
    flow->step(state, dt);
    ib->finish_step(state);
  }
};

}  // namespace valsalva::test
