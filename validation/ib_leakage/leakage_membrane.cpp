// The leakage channel's membrane as a finite-element solid; see leakage_membrane.hpp.
#include "validation/ib_leakage/leakage_membrane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "structure/solid_forces.hpp"
#include "structure/static_solver.hpp"

namespace valsalva::validation {

Eigen::Matrix3Xd membrane_static_shape(const structure::SolidMesh& membrane,
                                       const structure::Material& material, double p) {
  structure::SolidForces forces(membrane, material);
  structure::StaticProblem prob;
  prob.forces = &forces;
  for (const char* wall : {"v0", "v1"})
    prob.dirichlet.push_back({membrane.node_set(wall), {true, true, true}, {}});
  std::vector<int> all(static_cast<std::size_t>(membrane.num_nodes()));
  for (int a = 0; a < membrane.num_nodes(); ++a) all[static_cast<std::size_t>(a)] = a;
  prob.dirichlet.push_back({all, {false, false, true}, {}});
  // u0 is the upstream face (outward normal -x): p > 0 pushes the membrane downstream.
  prob.pressures.push_back({membrane.surface_set("u0"), p});
  structure::NewtonOptions o;
  o.load_steps = 10;
  o.damping = 1e-2;  // a flat membrane has only its bending stiffness at the start
  o.rtol = 1e-6;     // thin 3D solid: round-off floor of the residual near 1e-7 (leaflet_closure)
  o.max_relaxation_steps = 400;
  const auto r = structure::solve_static(prob, o);
  if (!r.converged)
    throw std::runtime_error("ib_leakage: static membrane reference did not converge: " +
                             r.diagnosis);
  return r.x;
}

double membrane_deflection(const structure::SolidMesh& membrane, const Eigen::Matrix3Xd& x) {
  return (x.row(0) - membrane.X.row(0)).maxCoeff();
}

std::vector<int> membrane_centre_line(const structure::SolidMesh& m, double x_m, double thickness) {
  std::vector<int> line;
  for (int a = 0; a < m.num_nodes(); ++a)
    if (std::abs(m.X(0, a) - x_m) < 1e-6 * thickness && std::abs(m.X(2, a)) < 1e-9)
      line.push_back(a);
  std::sort(line.begin(), line.end(), [&](int a, int b) { return m.X(1, a) < m.X(1, b); });
  return line;
}

}  // namespace valsalva::validation
