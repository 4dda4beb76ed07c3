// Evaluations of the DFG cylinder's wall at the end of the 2D-1 run (validation/dfg_cylinder):
// the stagnation pressures as the normal traction of the residual force, and the split of c_L
// into its flux contributions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "flow/projection_rk4.hpp"
#include "flow/wall_force.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::validation {

struct CylinderFluid {
  double rho = 1, nu = 1e-3, diameter = 0.1;  // kg/m3, m2/s, m
};

// 2D-1 end state, other evaluations: c_L split into the pressure, viscous and convective
// fluxes of the residual force, and the surface integral of the nodal p; the stagnation
// pressures of the wall nodes, of the traction, and extrapolated along the axis from probes at
// 1, 2, 3 size_near off the wall.
struct EndDiagnostics {
  double cl_pressure = 0, cl_viscous = 0, cl_convective = 0, cl_surface_pressure = 0;
  double p_front_wall_node = 0, p_back_wall_node = 0;  // probes at the wall nodes
  double p_front = 0, p_back = 0;                      // normal traction of the residual force
  double p_front_linear = 0, p_back_linear = 0;        // 2 p1 - p2
  double p_front_quadratic = 0, p_back_quadratic = 0;  // 3 p1 - 3 p2 + p3
};

// Stagnation pressure as the normal traction of the residual force (flow::wall_loads): at a
// no-slip wall the viscous normal stress vanishes, so p = F_j . A_j / |A_j|^2 with F_j the
// reaction of the wall node's dual volume and A_j its wall area (summed over the layers). The
// nodal p of a wall node has no momentum balance; only its continuity row with the dt-scaled
// pressure damping sets it, and it carries a wall-normal odd-even mode that grows as dt
// shrinks (size 0.01 / 0.04, sigma 0.5 / 0.25 / 0.125: nodal dp 0.12103 / 0.12196 / 0.12319,
// traction dp 0.11862 / 0.11850 / 0.11841; size 0.005 / 0.02, sigma 0.5 -> 0.25 on the front
// axis: the wall nodes' p +8e-4, the next three nodes out -6e-4, +2e-4, -1e-4). The reaction
// averages p_j with its neighbours (faces carry (p_j + p_k) / 2), where that mode cancels.
// Interpolated to the axis by the parabola in y through the three nearest cylinder positions on
// each side: an odd segment count puts no node on the axis, and a straight line between the two
// nodes at +-2.9 degrees cut the front pressure's maximum (size 0.005 / 0.02: dp 0.11729 linear,
// 0.11776 parabolic).
class StagnationTraction {
 public:
  StagnationTraction(const mesh::Mesh& mesh, double centre_x, double centre_y, double radius) {
    for (int side = 0; side < 2; ++side) {  // 0: front (x < centre), 1: back
      std::vector<Eigen::Vector2d> near;    // distinct positions on the circle, by |y - centre_y|
      for (const Eigen::Vector3d& x : mesh.nodes) {
        const double dx = x.x() - centre_x, dy = x.y() - centre_y;
        if (std::abs(std::hypot(dx, dy) - radius) > 1e-9 || (dx > 0) != (side == 1)) continue;
        if (std::none_of(near.begin(), near.end(),
                         [&](const Eigen::Vector2d& q) { return (q - x.head<2>()).norm() < 1e-9; }))
          near.push_back(x.head<2>());
      }
      std::sort(near.begin(), near.end(), [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return std::abs(a.y() - centre_y) < std::abs(b.y() - centre_y);
      });
      for (int i = 0; i < 3; ++i) {  // Lagrange weights at y = centre_y
        double w = 1;
        for (int k = 0; k < 3; ++k)
          if (k != i) w *= (centre_y - near[k].y()) / (near[i].y() - near[k].y());
        points_[side][i] = {near[i], w};
      }
    }
  }
  // p at the front and the back stagnation point. Collective.
  std::pair<double, double> pressures(const mesh::LocalMesh& local,
                                      const std::vector<flow::WallLoad>& loads) const {
    std::array<double, 36> sums{};  // per side and position: force, area
    for (const auto& l : loads)
      for (int k = 0; k < 6; ++k)
        if ((local.position[l.node].head<2>() - points_[k / 3][k % 3].xy).norm() < 1e-9)
          for (int c = 0; c < 3; ++c)
            sums[6 * k + c] += l.force[c], sums[6 * k + 3 + c] += l.area[c];
    local.comm.sum_in_place(sums);
    double p[2] = {0, 0};
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector3d f(&sums[6 * k]), a(&sums[6 * k + 3]);
      p[k / 3] += points_[k / 3][k % 3].weight * f.dot(a) / a.squaredNorm();
    }
    return {p[0], p[1]};
  }

 private:
  struct Point {
    Eigen::Vector2d xy;
    double weight;
  };
  std::array<std::array<Point, 3>, 2> points_;
};

EndDiagnostics end_diagnostics(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                               const mesh::LocalMesh& local, const flow::ProjectionRK4& solver,
                               const flow::FlowState& state, double yc, double zc, double delta,
                               double q, const CylinderFluid& fluid);  // q: 0.5 rho U^2 D depth

}  // namespace valsalva::validation
