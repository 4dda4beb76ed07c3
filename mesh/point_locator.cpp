#include "mesh/point_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace valsalva::mesh {

namespace {

using mesh::CellType;

Eigen::Vector3d reference_centre(CellType type) {
  switch (type) {
    case CellType::tetra:
      return {0.25, 0.25, 0.25};
    case CellType::prism:
      return {1.0 / 3.0, 1.0 / 3.0, 0.0};
    case CellType::pyramid:
      return {0.0, 0.0, 0.25};
    case CellType::hexa:
      break;
  }
  return {0.0, 0.0, 0.0};
}

bool inside_reference(CellType type, const Eigen::Vector3d& r, double tol) {
  switch (type) {
    case CellType::tetra:
      return r.minCoeff() >= -tol && 1.0 - r.sum() >= -tol;
    case CellType::hexa:
      return r.cwiseAbs().maxCoeff() <= 1.0 + tol;
    case CellType::prism:
      return r.x() >= -tol && r.y() >= -tol && 1.0 - r.x() - r.y() >= -tol &&
             std::abs(r.z()) <= 1.0 + tol;
    case CellType::pyramid:
      return r.z() >= -tol && r.z() <= 1.0 + tol && std::abs(r.x()) <= 1.0 - r.z() + tol &&
             std::abs(r.y()) <= 1.0 - r.z() + tol;
  }
  return false;
}

}  // namespace

int shape_functions(CellType type, const Eigen::Vector3d& xi, std::array<double, 8>& n,
                    std::array<Eigen::Vector3d, 8>& dn) {
  const double x = xi.x(), y = xi.y(), z = xi.z();
  switch (type) {
    case CellType::tetra:
      n[0] = 1 - x - y - z, n[1] = x, n[2] = y, n[3] = z;
      dn[0] = {-1, -1, -1}, dn[1] = {1, 0, 0}, dn[2] = {0, 1, 0}, dn[3] = {0, 0, 1};
      return 4;
    case CellType::hexa: {
      static const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
      for (int k = 0; k < 8; ++k) {
        const double a = 1 + s[k][0] * x, b = 1 + s[k][1] * y, c = 1 + s[k][2] * z;
        n[k] = a * b * c / 8;
        dn[k] = Eigen::Vector3d(s[k][0] * b * c, s[k][1] * a * c, s[k][2] * a * b) / 8;
      }
      return 8;
    }
    case CellType::prism: {
      const double t[3] = {1 - x - y, x, y};
      const Eigen::Vector3d dt[3] = {{-1, -1, 0}, {1, 0, 0}, {0, 1, 0}};
      for (int k = 0; k < 6; ++k) {
        const double s = k < 3 ? -1.0 : 1.0, l = (1 + s * z) / 2;
        n[k] = t[k % 3] * l;
        dn[k] = dt[k % 3] * l + Eigen::Vector3d(0, 0, t[k % 3] * s / 2);
      }
      return 6;
    }
    case CellType::pyramid: {
      static const int s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      const double a = std::max(1 - z, 1e-12);  // the rational functions' apex limit
      for (int k = 0; k < 4; ++k) {
        const double p = a + s[k][0] * x, q = a + s[k][1] * y;
        n[k] = p * q / (4 * a);
        const double df_da = (p + q) / a - p * q / (a * a);
        dn[k] = Eigen::Vector3d(s[k][0] * q / (4 * a), s[k][1] * p / (4 * a), -df_da / 4);
      }
      n[4] = z, dn[4] = {0, 0, 1};
      return 5;
    }
  }
  return 0;
}

PointLocator::PointLocator(const mesh::Mesh& mesh) : mesh_(&mesh) {
  lo_ = Eigen::Vector3d::Constant(INFINITY);
  hi_ = -lo_;
  for (const auto& x : mesh.nodes) lo_ = lo_.cwiseMin(x), hi_ = hi_.cwiseMax(x);
  // Group the cells by the binary exponent of their largest half-extent (ascending ids within a
  // group); each group's buckets are as wide as its largest cell.
  std::map<int, SizeGroup> by_size;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    Eigen::Vector3d a = Eigen::Vector3d::Constant(INFINITY), b = -a;
    for (auto v : mesh.cell(c)) a = a.cwiseMin(mesh.nodes[v]), b = b.cwiseMax(mesh.nodes[v]);
    const double half = 0.5 * (b - a).maxCoeff();
    SizeGroup& group = by_size[half > 0 ? std::ilogb(half) : std::numeric_limits<int>::min()];
    group.reach = std::max(group.reach, half);
    group.centres.push_back(0.5 * (a + b));
    group.cells.push_back(c);
  }
  groups_.reserve(by_size.size());  // no reallocation once a grid views its group's centres
  for (auto& [exponent, group] : by_size) {
    groups_.push_back(std::move(group));
    SizeGroup& g = groups_.back();
    g.grid = core::BucketGrid(g.centres, std::max(2 * g.reach, 1e-300));
  }
}

std::optional<PointLocation> PointLocator::try_cell(mesh::GlobalIndex c, const Eigen::Vector3d& x,
                                                    double tolerance) const {
  const auto cell = mesh_->cell(c);
  const CellType type = mesh_->cell_types[c];
  Eigen::Vector3d a = Eigen::Vector3d::Constant(INFINITY), b = -a;
  for (auto v : cell) a = a.cwiseMin(mesh_->nodes[v]), b = b.cwiseMax(mesh_->nodes[v]);
  const double size = (b - a).maxCoeff();
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(tolerance * size);
  if ((x.array() < (a - pad).array()).any() || (x.array() > (b + pad).array()).any())
    return std::nullopt;

  PointLocation loc;
  loc.cell = c;
  loc.count = static_cast<int>(cell.size());
  for (int k = 0; k < loc.count; ++k) loc.nodes[k] = cell[k];
  // A cell node itself: exact weight 1 (also the pyramid apex, where the map is singular).
  for (int k = 0; k < loc.count; ++k)
    if ((mesh_->nodes[cell[k]] - x).norm() <= 1e-12 * size) {
      loc.weights.fill(0.0);
      loc.weights[k] = 1.0;
      return loc;
    }
  std::array<Eigen::Vector3d, 8> dn;
  Eigen::Vector3d xi = reference_centre(type);
  bool converged = false;
  for (int it = 0; it < 30 && !converged; ++it) {
    loc.count = shape_functions(type, xi, loc.weights, dn);
    Eigen::Vector3d r = -x;
    Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
    for (int k = 0; k < loc.count; ++k) {
      r += loc.weights[k] * mesh_->nodes[cell[k]];
      jac += mesh_->nodes[cell[k]] * dn[k].transpose();
    }
    const Eigen::Vector3d step = jac.partialPivLu().solve(r);
    if (!step.allFinite()) return std::nullopt;
    xi -= step;
    converged = step.norm() < 1e-13 * (1.0 + xi.norm());
  }
  if (!converged || !inside_reference(type, xi, tolerance)) return std::nullopt;
  loc.count = shape_functions(type, xi, loc.weights, dn);
  loc.reference = xi;
  return loc;
}

std::optional<PointLocation> PointLocator::locate(const Eigen::Vector3d& x,
                                                  double tolerance) const {
  for (int d = 0; d < 3; ++d) {
    const double margin = tolerance * (hi_[d] - lo_[d]) + 1e-300;
    if (x[d] < lo_[d] - margin || x[d] > hi_[d] + margin || !std::isfinite(x[d]))
      return std::nullopt;
  }
  // A cell whose box, padded by tolerance x its size (try_cell), holds x has its box centre
  // within (1 + 2 tolerance) x its half-extent of x in every coordinate (1e-12: rounding).
  std::vector<mesh::GlobalIndex> candidates;
  std::vector<int> found;
  for (const SizeGroup& g : groups_) {
    g.grid.in_box(x, g.reach * (1 + 2 * std::max(tolerance, 0.0) + 1e-12) + 1e-300, found);
    for (int k : found) candidates.push_back(g.cells[k]);
  }
  std::sort(candidates.begin(), candidates.end());
  for (mesh::GlobalIndex c : candidates)
    if (auto loc = try_cell(c, x, tolerance)) return loc;
  return std::nullopt;
}

}  // namespace valsalva::mesh
