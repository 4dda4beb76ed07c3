#include "valve/leaflet_closing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "structure/material.hpp"
#include "structure/stress_recovery.hpp"

namespace valsalva::valve {

namespace {

using structure::Vec3;

void check(const ClosingOptions& o) {
  auto require = [](bool ok, const char* what, double value, const char* limit) {
    if (!ok)
      throw std::invalid_argument(fmt::format("close-leaflets: {} = {} ({})", what, value, limit));
  };
  require(std::isfinite(o.pressure) && o.pressure > 0, "pressure", o.pressure,
          "must be a positive number of pascals");
  require(o.shear_modulus > 0, "shear modulus", o.shear_modulus, "must be > 0");
  require(o.bulk_modulus > 0, "bulk modulus", o.bulk_modulus, "must be > 0");
  require(o.load_steps >= 1 && o.load_steps <= 1000, "load steps", o.load_steps,
          "must be in [1, 1000]");
  require(o.rtol > 0 && o.rtol < 1, "tolerance", o.rtol, "must be in (0, 1)");
  require(o.damping >= 0, "damping", o.damping, "must be >= 0");
}

// Mean distance between the centres of each aortic face and the opposite face of its element.
double mean_thickness(const structure::SolidMesh& mesh, const std::vector<LeafletGroups>& ls) {
  double sum = 0;
  long n = 0;
  const int nen = mesh.nodes_per_element();
  std::vector<double> N(nen), dN(3 * nen);
  for (const auto& l : ls)
    for (const auto& f : mesh.surface_set(l.aortic_face)) {
      const structure::HexFace hf = structure::hex_face(f.face);
      Vec3 ends[2];
      for (int s = 0; s < 2; ++s) {
        Vec3 xi = Vec3::Zero();
        xi[hf.axis] = s ? 1.0 : -1.0;
        structure::hex_shape(mesh.order, xi, N, dN);
        ends[s] = Vec3::Zero();
        for (int a = 0; a < nen; ++a)
          ends[s] += N[a] * mesh.X.col(mesh.element_nodes(f.element)[a]);
      }
      sum += (ends[1] - ends[0]).norm();
      ++n;
    }
  return sum / n;
}

// The leaflet's centre direction in the annulus plane's axes: the mean in-plane direction of its
// attachment nodes (unit, z = 0).
Vec3 centre_direction(const structure::SolidMesh& mesh, const LeafletGroups& l,
                      const structure::ValveBasis& b) {
  Vec3 c = Vec3::Zero();
  for (int n : mesh.node_set(l.attachment)) {
    Vec3 p = b.to_local(mesh.X.col(n));
    p.z() = 0;
    c += p.normalized();
  }
  return c.normalized();
}

// The free-edge node in the middle of the leaflet: closest in angle to the leaflet's centre
// direction, then the middle one through the thickness.
int free_edge_midpoint(const structure::SolidMesh& mesh, const LeafletGroups& l,
                       const structure::ValveBasis& b) {
  const Vec3 c = centre_direction(mesh, l, b);
  const double centre = std::atan2(c.y(), c.x());
  auto angle_off = [&](int n) {
    const Vec3 p = b.to_local(mesh.X.col(n));
    return std::abs(std::remainder(std::atan2(p.y(), p.x()) - centre, 2 * M_PI));
  };
  const auto& edge = mesh.node_set(l.free_edge);
  double best = std::numeric_limits<double>::infinity();
  for (int n : edge) best = std::min(best, angle_off(n));
  std::vector<std::pair<double, int>> row;  // (radius, node) of the nodes at that angle
  for (int n : edge)
    if (angle_off(n) <= best + 1e-6) {
      const Vec3 p = b.to_local(mesh.X.col(n));
      row.push_back({std::hypot(p.x(), p.y()), n});
    }
  std::sort(row.begin(), row.end());
  return row[row.size() / 2].second;
}

// For every leaflet, the planes through the valve axis and the commissures it shares with its
// neighbours (the bisectors of the centre directions of neighbouring leaflets), each with its
// normal towards the leaflet; its aortic and ventricular faces must stay on that side. A
// clearance c moves each plane c / 2 towards its leaflet, so neighbours stay c apart.
std::vector<structure::RigidObstacle> commissure_planes(const structure::SolidMesh& mesh,
                                                        const std::vector<LeafletGroups>& ls,
                                                        const structure::ValveBasis& b,
                                                        double clearance) {
  std::vector<Vec3> centre;
  for (const auto& l : ls) centre.push_back(centre_direction(mesh, l, b));
  auto global = [&](const Vec3& v) { return Vec3(v.x() * b.e1 + v.y() * b.e2); };
  std::vector<structure::RigidObstacle> planes;
  for (std::size_t i = 0; i < ls.size(); ++i) {
    const auto faces =
        structure::contact_surface(mesh, {ls[i].aortic_face, ls[i].ventricular_face});
    // The neighbours: the nearest centre direction on either side.
    for (const double side : {1.0, -1.0}) {
      std::size_t next = i;
      double best = 4;
      for (std::size_t j = 0; j < ls.size(); ++j) {
        const double turn =
            std::atan2(centre[i].cross(centre[j]).z(), centre[i].dot(centre[j])) * side;
        if (j != i && turn > 0 && turn < best) {
          best = turn;
          next = j;
        }
      }
      if (next == i) continue;
      if ((centre[i] + centre[next]).norm() < 1e-6)
        throw std::invalid_argument(fmt::format(
            "close-leaflets: {} and {} face each other across the axis, so the plane between "
            "them is not defined by their centres; use --coaptation leaflets",
            ls[i].name, ls[next].name));
      const Vec3 commissure = (centre[i] + centre[next]).normalized();
      const Vec3 normal = (centre[i] - centre[i].dot(commissure) * commissure).normalized();
      structure::RigidObstacle plane;
      plane.name = fmt::format("{}-plane-{}", ls[i].name, ls[next].name);
      plane.shape = structure::RigidObstacle::Shape::plane;
      plane.direction = global(normal);
      plane.point = b.origin + 0.5 * clearance * plane.direction;
      plane.faces = faces;
      planes.push_back(plane);
    }
  }
  return planes;
}

}  // namespace

ClosingResult close_leaflets(const structure::SolidMesh& mesh, const structure::ValveFrame& valve,
                             const ClosingOptions& options) {
  check(options);
  const structure::ValveBasis basis = structure::valve_basis(valve);
  ClosingResult r;
  r.leaflets = leaflet_groups(mesh);
  r.thickness = mean_thickness(mesh, r.leaflets);

  const auto material = structure::make_neo_hookean(options.shear_modulus, options.bulk_modulus);
  structure::SolidForces forces(mesh, *material);
  structure::StaticProblem problem;
  problem.forces = &forces;
  for (const auto& l : r.leaflets) {
    problem.dirichlet.push_back({mesh.node_set(l.attachment), {true, true, true}, {}});
    // Positive pressure pushes into the solid: on the aortic face, towards the ventricle side.
    problem.pressures.push_back({mesh.surface_set(l.aortic_face), options.pressure});
  }
  const Coaptation coaptation = options.contact ? options.coaptation : Coaptation::none;
  if (coaptation == Coaptation::leaflets)
    for (std::size_t a = 0; a < r.leaflets.size(); ++a)
      for (std::size_t b = a + 1; b < r.leaflets.size(); ++b) {
        const auto& la = r.leaflets[a];
        const auto& lb = r.leaflets[b];
        problem.contact.push_back(
            {la.name + "-" + lb.name,
             structure::contact_surface(mesh, {la.aortic_face, la.ventricular_face}),
             structure::contact_surface(mesh, {lb.aortic_face, lb.ventricular_face})});
      }
  if (coaptation == Coaptation::planes)
    problem.obstacles =
        commissure_planes(mesh, r.leaflets, basis, options.contact_options.clearance);
  problem.contact_options = options.contact_options;
  structure::NewtonOptions newton;
  newton.load_steps = options.load_steps;
  newton.damping = options.damping;
  newton.rtol = options.rtol;
  newton.max_relaxation_steps = options.max_relaxation_steps;
  newton.verbose = options.verbose;
  if (coaptation != Coaptation::none)
    newton.admissible = [&](const Eigen::Matrix3Xd& x) {
      return !leaflets_cross(mesh, x, r.leaflets);
    };
  const auto t0 = std::chrono::steady_clock::now();
  r.newton = structure::solve_static(problem, newton);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const Eigen::Matrix3Xd& x = r.newton.x;
  for (const auto& l : r.leaflets) {
    FreeEdgeMidpoint m;
    m.node = free_edge_midpoint(mesh, l, basis);
    const Vec3 p = basis.to_local(x.col(m.node));
    m.radial = std::hypot(p.x(), p.y());
    m.axial = p.z();
    r.free_edge_midpoints.push_back(m);
  }
  r.pairs = leaflet_pairs(mesh, x, r.leaflets, valve, 1.5 * r.thickness);
  const structure::LeafletPositions all{&mesh, &x};
  structure::OrificeOptions orifice_options;
  orifice_options.list_uncovered = true;  // close-leaflets draws where the holes are
  r.orifice = structure::geometric_orifice_area({&all, 1}, valve, orifice_options);
  r.stress = structure::von_mises_summary(forces, x, 99);
  const int corner = mesh.element_nodes(r.stress.max_element)[0];
  for (std::size_t k = 0; k < r.leaflets.size(); ++k) {
    const auto& set = mesh.node_set(r.leaflets[k].name);
    if (std::binary_search(set.begin(), set.end(), corner)) r.max_stress_leaflet = int(k);
  }
  r.max_stress_to_attachment = std::numeric_limits<double>::infinity();
  for (const auto& l : r.leaflets)
    for (int n : mesh.node_set(l.attachment))
      r.max_stress_to_attachment =
          std::min(r.max_stress_to_attachment, (x.col(n) - r.stress.max_position).norm());
  return r;
}

}  // namespace valsalva::valve
