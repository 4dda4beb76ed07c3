// The closed-valve leakage channel; see leakage_channel.hpp.
#include "validation/ib_leakage/leakage_channel.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "flow/poisson_weights.hpp"
#include "io/box_generator.hpp"
#include "structure/mesh_generators.hpp"
#include "structure/static_solver.hpp"

namespace valsalva::validation {

namespace {

int cells(double length, double h) {
  return static_cast<int>(std::lround(length / h));
}

flow::Mesh channel_mesh(const LeakageSetup& s) {
  io::BoxSpec box;
  box.length = {s.length(), s.height, s.depth()};
  box.cells = {cells(s.length(), s.h), cells(s.height, s.h), s.depth_cells};
  box.periodic = {false, false, true};
  return io::generate_box(box);
}

structure::SolidMesh membrane_mesh(const LeakageSetup& s) {
  const double x0 = s.membrane_x() - s.thickness / 2;
  return structure::structured_block(
      structure::HexOrder::q2, {1, cells(s.height, s.h), s.depth_cells},
      [&](const structure::Vec3& u) {
        return structure::Vec3(x0 + s.thickness * u.x(), s.height * u.y(), s.depth() * u.z());
      });
}

}  // namespace

LeakageChannel::LeakageChannel(const LeakageSetup& s, MPI_Comm comm)
    : setup(s), mesh(channel_mesh(s)), metrics(flow::compute_dual_metrics(mesh)) {
  if (!(s.h > 0) || s.kernel_width * s.h >= s.depth() || !(s.thickness > 0))
    throw std::invalid_argument(fmt::format(
        "ib_leakage: h = {} m, kernel width {} h, thickness {} m: need h > 0, thickness > 0 and "
        "the kernel narrower than the slab depth {} cells",
        s.h, s.kernel_width, s.thickness, s.depth_cells));
  // Ghost layers are breadth-first on the edge graph (Manhattan distance on hexahedra): a
  // marker's support reaches floor(width / 2 + 1/2) cells per axis from its nearest (owned)
  // node, so 3 times that, plus one layer that the support must not touch.
  const int layers = 3 * static_cast<int>(std::floor(s.kernel_width / 2 + 0.5)) + 1;
  local = flow::distribute(mesh, metrics, comm, {layers, "metis"});
  auto inlet = flow::boundary_spec("xmin", flow::BoundaryType::pressure_outlet);
  auto outlet = flow::boundary_spec("xmax", flow::BoundaryType::pressure_outlet);
  const double nu = s.viscosity / s.density;
  bc = std::make_shared<flow::BoundaryConditions>(
      local,
      std::vector<flow::BoundarySpec>{inlet, outlet,
                                      flow::boundary_spec("ymin", flow::BoundaryType::wall),
                                      flow::boundary_spec("ymax", flow::BoundaryType::wall)},
      nu);
  inlet_patch = mesh.patch_index("xmin");
  outlet_patch = mesh.patch_index("xmax");
  // p_in is ramped by writing it into the pressure at the xmin Dirichlet nodes before each step
  // (the projection keeps dp = 0 there, so p^n at those nodes is the imposed value).
  const auto fixed = bc->pressure_dirichlet();
  for (int j = 0; j < local.num_local(); ++j)
    if (fixed[j] && local.position[j].x() < s.length() / 2) inlet_nodes.push_back(j);

  flow::ProjectionOptions fluid;
  fluid.density = s.density;
  fluid.viscosity = nu;
  fluid.boundary = bc;
  fluid.poisson.dirichlet = bc->pressure_dirichlet();
  flow = std::make_unique<flow::ProjectionRK4>(local, fluid,
                                               flow::poisson_weights(mesh, metrics, local));

  membrane = membrane_mesh(s);
  material = structure::make_neo_hookean(s.G, s.K);
  ibm::ImmersedOptions options;
  options.transfer.kernel = {ibm::KernelType::peskin4, s.kernel_width};
  options.fluid_density = s.density;
  options.box = ibm::PeriodicBox{Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d(s.length(), s.height, s.depth()),
                                 {false, false, true}};
  ib = std::make_unique<ibm::ImmersedStructure>(local, options);
  ib->add_body(membrane, *material, {"membrane", {"v0", "v1"}, s.G * s.h * s.tether_factor});
  flow->set_body_force(ib->body_force());
}

double LeakageChannel::inlet_pressure(double t) const {
  if (t >= setup.ramp) return setup.pressure;
  const double s = t / setup.ramp;
  return setup.pressure * s * s * s * (10 - 15 * s + 6 * s * s);
}

}  // namespace valsalva::validation
