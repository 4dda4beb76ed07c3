// A periodic box of hexahedra with the flow solver and an immersed block: the set-up shared by
// the coupling and stability tests.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <memory>

#include "flow/projection_rk4.hpp"
#include "ibm/immersed_structure.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
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
  ibm::ImplicitVariant implicit_variant = ibm::ImplicitVariant::lagged;
  int implicit_newton_iterations = 1;  // ImmersedOptions: Newton on the lagged solve's force
  flow::TimeScheme time_scheme = flow::TimeScheme::rk4_jameson;  // fluid and markers
  // The skew-symmetric convection conserves momentum up to the divergence the Poisson solve
  // leaves (flow/projection_rk4.hpp); tests of momentum at round-off tighten it.
  double poisson_tolerance = 1e-8;
  MPI_Comm comm = MPI_COMM_WORLD;
  // Instead of the stretched cube: two slabs side x side x side/2 (3x3 and 2x2 elements), the
  // upper one sunk `overlap` into the lower one, with contact between them.
  bool contact_slabs = false;
  double overlap = 0.02;
  bool contact = true;  // with contact_slabs: false builds the same slabs without contact
  // Clamped node sets of the block, e.g. {"u0"}, held as `clamp` says.
  std::vector<std::string> clamped_sets;
  ibm::Clamp clamp = ibm::Clamp::fixed;
  double tether_stiffness = 0;
  structure::ContactOptions::Formulation formulation =
      structure::ContactOptions::Formulation::two_pass;
};

struct IbBox {
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  structure::SolidMesh solid;
  std::unique_ptr<structure::Material> material;
  std::unique_ptr<flow::ProjectionRK4> flow;
  std::unique_ptr<ibm::ImmersedStructure> ib;
  flow::FlowState state;

  explicit IbBox(const IbBoxSpec& s) {
    mesh::BoxSpec box;
    box.cells = {s.cells, s.cells, s.cells};
    box.periodic = {true, true, true};
    mesh = mesh::generate_box(box);
    metrics = mesh::compute_dual_metrics(mesh);
    local = mesh::distribute(mesh, metrics, s.comm, {4, mesh::PartitionMethod::metis});
    const Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.5 - s.side / 2);
    solid =
        structure::structured_block(structure::HexOrder::q2, {s.elements, s.elements, s.elements},
                                    [&](const structure::Vec3& u) { return lo + s.side * u; });
    material = structure::make_neo_hookean(s.shear_modulus, 10 * s.shear_modulus);
    ibm::BodySpec body{"block", s.clamped_sets, s.tether_stiffness};
    body.clamp = s.clamp;
    if (s.contact_slabs) {
      solid = {};
      const double z0 = 0.5 - s.side / 2, z1 = 0.5, t = s.side / 2;
      auto slab = [&](int n, double zlo) {
        return structure::structured_block(
            structure::HexOrder::q2, {n, n, 1}, [&](const structure::Vec3& u) {
              return structure::Vec3(lo.x() + s.side * u[0], lo.y() + s.side * u[1],
                                     zlo + t * u[2]);
            });
      };
      structure::append_body(solid, slab(3, z0), "lower_");
      structure::append_body(solid, slab(2, z1 - s.overlap), "upper_");
      if (s.contact)
        body.contact.push_back(
            {"slabs", solid.surface_set("lower_w1"), solid.surface_set("upper_w0")});
      body.contact_options.formulation = s.formulation;
    }
    flow::ProjectionOptions fluid;
    fluid.density = s.density;
    fluid.viscosity = s.viscosity;
    fluid.poisson.tolerance = s.poisson_tolerance;
    fluid.time_scheme = s.time_scheme;
    flow = std::make_unique<flow::ProjectionRK4>(local, fluid);
    ibm::ImmersedOptions options;
    options.mode = s.mode;
    options.implicit_variant = s.implicit_variant;
    options.implicit_newton_iterations = s.implicit_newton_iterations;
    options.time_scheme = s.time_scheme;
    options.fluid_density = s.density;
    options.box = ibm::PeriodicBox{};
    options.box->periodic = {true, true, true};
    ib = std::make_unique<ibm::ImmersedStructure>(local, options);
    ib->set_projector([this](flow::VectorField& v, flow::ScalarField& q) { flow->project(v, q); });
    ib->add_body(solid, *material, body);
    // Isochoric stretch about the box centre as the initial marker positions.
    const double stretch = s.contact_slabs ? 1.0 : s.stretch;
    const Eigen::Vector3d scale(stretch, 1 / std::sqrt(stretch), 1 / std::sqrt(stretch));
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

// Largest marker difference between `box` and the same box run on one rank for `steps` steps of
// dt (call after `box` made those steps).
inline double marker_difference_to_serial(IbBoxSpec spec, const IbBox& box, int steps, double dt) {
  spec.comm = MPI_COMM_SELF;
  IbBox serial(spec);
  for (int n = 0; n < steps; ++n) serial.step(dt);
  return (serial.ib->positions() - box.ib->positions()).cwiseAbs().maxCoeff();
}

}  // namespace valsalva::test
