#include "ibm/dirac_transfer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <ctime>
#include <limits>

#include "ibm/collective_error.hpp"
#include "ibm/rkpm.hpp"

namespace valsalva::ibm {

namespace {

std::string where(int marker, const Eigen::Vector3d& x) {
  return fmt::format("ibm: marker {} at ({:.6g}, {:.6g}, {:.6g}) m", marker, x.x(), x.y(), x.z());
}

double median(std::vector<double> v) {
  if (v.empty()) return 1.0;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

DiracTransfer::DiracTransfer(mesh::LocalMesh& mesh, const TransferOptions& options)
    : mesh_(&mesh), options_(options) {
  if (!(options.kernel.width > 0))
    throw std::invalid_argument(
        fmt::format("ibm: kernel width {} must be > 0 (in units of h)", options.kernel.width));
  if (!(options.growth_factor > 1) || options.max_growth < 0)
    throw std::invalid_argument(fmt::format("ibm: growth factor {} must be > 1, max growth {} >= 0",
                                            options.growth_factor, options.max_growth));
  // Buckets about one mesh size wide: a 4h support box visits ~125 buckets of ~1 node each.
  grid_ = core::BucketGrid(mesh.position, median(mesh.h));
  for (double h : mesh.h) h_max_ = std::max(h_max_, h);
  int outer = 0;
  for (int layer : mesh.ghost_layer) outer = std::max(outer, layer);
  outer_layer_ = static_cast<int>(mesh.comm.max(static_cast<std::int64_t>(outer)));
  // Ghost positions are those of the periodic representative, so an edge whose vector differs
  // from the position difference crosses a periodic boundary by one period (up to sign).
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [a, b] = mesh.edges[e];
    const Eigen::Vector3d gap = mesh.edge_vector[e] - (mesh.position[b] - mesh.position[a]);
    if (gap.norm() <= 1e-8 * mesh.edge_vector[e].norm()) continue;
    // Corner edges cross several periodic planes at once: split the gap by axis.
    for (int d = 0; d < 3; ++d) {
      if (std::abs(gap[d]) <= 1e-8 * gap.norm()) continue;
      Eigen::Vector3d period = Eigen::Vector3d::Zero();
      period[d] = std::abs(gap[d]);
      const bool known = std::any_of(periods_.begin(), periods_.end(), [&](const auto& p) {
        return (p - period).norm() <= 1e-8 * period.norm();
      });
      if (!known) periods_.push_back(period);
    }
  }
  boundary_normal_.assign(mesh.position.size(), Eigen::Vector3d::Zero());
  boundary_patch_.assign(mesh.position.size(), -1);
  std::vector<double> largest(mesh.position.size(), 0.0);
  for (const auto& b : mesh.boundary) {
    boundary_normal_[b.node] += b.area;
    if (b.area.norm() > largest[b.node])
      largest[b.node] = b.area.norm(), boundary_patch_[b.node] = b.patch;
  }
  for (auto& n : boundary_normal_)
    if (n.norm() > 0) n.normalize();
  images_.assign(1, Eigen::Vector3d::Zero());
  for (const auto& p : periods_) {
    const std::size_t n = images_.size();
    for (std::size_t k = 0; k < n; ++k) {
      images_.push_back(images_[k] + p);
      images_.push_back(images_[k] - p);
    }
  }
}

namespace {
// Adds the CPU time of its scope to `total` (std::clock: this process's CPU time).
class CpuTimer {
 public:
  explicit CpuTimer(double& total) : total_(total), start_(std::clock()) {}
  ~CpuTimer() { total_ += double(std::clock() - start_) / CLOCKS_PER_SEC; }
  CpuTimer(const CpuTimer&) = delete;
  CpuTimer& operator=(const CpuTimer&) = delete;

 private:
  double& total_;
  std::clock_t start_;
};
}  // namespace

void DiracTransfer::locate(std::span<const Eigen::Vector3d> markers) {
  const CpuTimer timer(counts_.cpu_seconds);
  num_markers_ = static_cast<int>(markers.size());
  supports_.clear();
  weights_.clear();
  ++counts_.calls;
  counts_.markers += num_markers_;
  counts_.rebuilt += num_markers_;
  locate_all(markers);
}

void DiracTransfer::relocate(std::span<const Eigen::Vector3d> markers) {
  if (!(options_.reuse_distance > 0) || located_at_.size() != markers.size()) {
    locate(markers);
    return;
  }
  // All markers or none: markers located at different times would lag their kernels by
  // different amounts, and forces that cancel between nearby markers (a thin leaflet's two
  // faces, contact pairs) would no longer cancel once spread. Located together, two markers'
  // kernels lag each other by their relative displacement only.
  bool moved = false;
  {
    const CpuTimer timer(counts_.cpu_seconds);
    for (std::size_t i = 0; i < markers.size() && !moved; ++i)
      moved =
          periodic_distance(markers[i], located_at_[i]) > options_.reuse_distance * located_h_[i];
  }
  if (moved) {
    locate(markers);
    return;
  }
  ++counts_.calls;
  counts_.markers += num_markers_;
}

double DiracTransfer::periodic_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  // A marker wrapped into the periodic box may come back one period away (a flap standing on
  // the periodic boundary sits at 0 or at the period by round-off).
  Eigen::Vector3d d = a - b;
  for (const auto& p : periods_) {
    const double length = p.norm();
    d -= p * std::round(d.dot(p) / (length * length));
  }
  return d.norm();
}

void DiracTransfer::locate_all(std::span<const Eigen::Vector3d> markers) {
  const auto& mesh = *mesh_;
  // Nearest owned node of every marker on this rank, then the rank with the nearest overall.
  // The search takes ghosts too, so that it stops as soon as any node is near (a marker of
  // another rank's region no longer scans every ring up to the reach): owned nodes are numbered
  // first and ties go to the lower index, so a ghost comes out only when every owned node is
  // strictly farther, and then the ghost's owner is strictly nearer and this rank cannot win.
  const double reach = options_.kernel.width * std::max(h_max_, options_.min_h);
  const std::size_t count = markers.size();
  mine_.resize(count);
  best_.resize(count);
  nearest_.resize(count);
  const int num_owned = mesh.num_owned;
  for (std::size_t k = 0; k < count; ++k) {
    const auto found = grid_.nearest(markers[k], reach, [](int) { return true; });
    const bool owned = found.index >= 0 && found.index < num_owned;
    nearest_[k] = owned ? found.index : -1;
    mine_[k] = {owned ? found.distance : std::numeric_limits<double>::max(), mesh.comm.rank()};
  }
  if (count > 0)
    VALSALVA_MPI(MPI_Allreduce(mine_.data(), best_.data(), static_cast<int>(count), MPI_DOUBLE_INT,
                               MPI_MINLOC, mesh.comm.get()));

  std::string error;
  built_h_.assign(count, 0.0);
  for (std::size_t k = 0; k < count && error.empty(); ++k) {
    const int marker = static_cast<int>(k);
    const auto& x = markers[k];
    if (best_[k].distance == std::numeric_limits<double>::max()) {
      error = fmt::format("{} is outside the fluid mesh: no fluid node within {:.6g} m",
                          where(marker, x), reach);
    } else if (best_[k].rank == mesh.comm.rank()) {
      error = build_support(marker, x, nearest_[k]);
      if (error.empty()) built_h_[k] = supports_.back().h;
    }
  }
  try {
    settle(mesh.comm, error);
  } catch (...) {
    located_at_.clear();  // the next relocate locates every marker again
    throw;
  }
  if (count > 0)
    VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, built_h_.data(), static_cast<int>(count), MPI_DOUBLE,
                               MPI_MAX, mesh.comm.get()));
  located_at_.assign(markers.begin(), markers.end());
  located_h_ = built_h_;
}

std::string DiracTransfer::build_support(int marker, const Eigen::Vector3d& x, int nearest) {
  const auto& mesh = *mesh_;
  const double h = std::max(mesh.h[static_cast<std::size_t>(nearest)], options_.min_h);
  KernelShape shape = options_.kernel;
  RkpmResult result;
  for (int attempt = 0; attempt <= options_.max_growth; ++attempt) {
    if (attempt > 0) shape.width *= options_.growth_factor;
    const double radius = support_radius(shape, h);
    for (const auto& p : periods_)
      if (2 * radius >= p.norm())
        return fmt::format(
            "{}: its kernel support ({:.6g} m wide) is wider than the period {:.6g} m",
            where(marker, x), 2 * radius, p.norm());
    candidates_.clear();
    offset_.clear();
    psi_.clear();
    volume_.clear();
    for (const auto& t : images_) {
      grid_.in_box(x - t, radius, found_);  // node j at its image x_j + t lies in the box
      for (int n : found_) {
        if (!mesh.frontier.empty() && mesh.frontier[n])
          return fmt::format(
              "{}: its kernel support (half-width {:.6g} m) reaches the edge of rank {}'s ghost "
              "nodes (ghost layer {} of at most {}), so nodes beyond it would be missed; widen "
              "the ghost region (partition.ghost_distance, partition.ghost_layers) or use a "
              "narrower kernel",
              where(marker, x), radius, mesh.comm.rank(), mesh.ghost_layer[n], outer_layer_);
        const Eigen::Vector3d y = mesh.position[n] + t - x;
        const double p = kernel_3d(shape, y, h);
        if (p <= 0.0) continue;
        candidates_.push_back(n);
        offset_.push_back(y);
        psi_.push_back(p);
        volume_.push_back(mesh.volume[n]);
      }
    }
    if (attempt == 0)
      if (auto outside = check_inside(marker, x, h); !outside.empty()) return outside;
    phi_.resize(candidates_.size());
    result = rkpm_correct(offset_, psi_, volume_, radius, options_.min_rcond, phi_);
    if (result.ok) break;
  }
  if (!result.ok)
    return fmt::format(
        "{}: the kernel's moment matrix is ill-conditioned (reciprocal condition number {:.3g} < "
        "{:.3g}) even with the support grown to {:.3g} h (h = {:.6g} m); the marker is probably "
        "outside the fluid or the mesh too coarse there",
        where(marker, x), result.rcond, options_.min_rcond, shape.width, h);
  MarkerSupport s{marker, h, shape.width, result.rcond, static_cast<int>(weights_.size()), 0};
  for (std::size_t k = 0; k < candidates_.size(); ++k)
    weights_.push_back({candidates_[k], phi_[k], offset_[k]});
  s.end = static_cast<int>(weights_.size());
  supports_.push_back(s);
  return {};
}

std::string DiracTransfer::check_inside(int marker, const Eigen::Vector3d& x, double h) const {
  // The nearest boundary node of the support (candidates_ / offset_ of the first attempt).
  int nearest = -1;
  double best = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    if (boundary_patch_[candidates_[k]] < 0 || offset_[k].squaredNorm() >= best) continue;
    best = offset_[k].squaredNorm();
    nearest = static_cast<int>(k);
  }
  if (nearest < 0) return {};
  const int node = candidates_[nearest];
  const double beyond = -offset_[nearest].dot(boundary_normal_[node]);
  if (beyond <= options_.max_outside * h) return {};
  const auto& at = mesh_->position[node];
  return fmt::format(
      "{} lies {:.6g} m ({:.3g} h) beyond the fluid boundary '{}' (outward normal of its node at "
      "({:.6g}, {:.6g}, {:.6g}) m); up to {:.3g} h is accepted: move the structure into the fluid",
      where(marker, x), beyond, beyond / h, mesh_->patch_names[boundary_patch_[node]], at.x(),
      at.y(), at.z(), options_.max_outside);
}

void DiracTransfer::check_sizes(const char* what, std::size_t marker_values,
                                std::size_t node_values, int components) const {
  const auto c = static_cast<std::size_t>(components);
  if (components < 1 || marker_values != c * static_cast<std::size_t>(num_markers_) ||
      node_values != c * static_cast<std::size_t>(mesh_->num_local()))
    throw std::invalid_argument(fmt::format(
        "ibm: {} got {} marker values and {} node values for {} located markers, {} local nodes "
        "and {} components",
        what, marker_values, node_values, num_markers_, mesh_->num_local(), components));
}

void DiracTransfer::spread(std::span<const double> marker_force, int components,
                           std::span<double> density) {
  check_sizes("spread", marker_force.size(), density.size(), components);
  const auto c = static_cast<std::size_t>(components);
  std::fill(density.begin(), density.end(), 0.0);
  for (const auto& s : supports_) {
    const double* force = &marker_force[c * static_cast<std::size_t>(s.marker)];
    for (int k = s.begin; k < s.end; ++k) {
      double* f = &density[c * static_cast<std::size_t>(weights_[k].node)];
      for (std::size_t d = 0; d < c; ++d) f[d] += force[d] * weights_[k].phi;
    }
  }
  mesh_->halo.exchange(density, components, mesh::HaloMode::add);
  mesh_->halo.exchange(density, components, mesh::HaloMode::insert);
}

void DiracTransfer::support_reach(std::span<double> reach) {
  check_sizes("support_reach", static_cast<std::size_t>(num_markers_), reach.size(), 1);
  std::fill(reach.begin(), reach.end(), 0.0);
  for (const auto& s : supports_)
    for (int k = s.begin; k < s.end; ++k) reach[weights_[k].node] += std::abs(weights_[k].phi);
  mesh_->halo.exchange(reach, 1, mesh::HaloMode::add);
  mesh_->halo.exchange(reach, 1, mesh::HaloMode::insert);
}

void DiracTransfer::interpolate(std::span<double> field, int components,
                                std::span<double> marker_values) {
  check_sizes("interpolate", marker_values.size(), field.size(), components);
  const auto c = static_cast<std::size_t>(components);
  mesh_->halo.exchange(field, components, mesh::HaloMode::insert);
  std::fill(marker_values.begin(), marker_values.end(), 0.0);
  for (const auto& s : supports_) {
    double* value = &marker_values[c * static_cast<std::size_t>(s.marker)];
    for (int k = s.begin; k < s.end; ++k) {
      const auto n = static_cast<std::size_t>(weights_[k].node);
      const double w = weights_[k].phi * mesh_->volume[n];
      for (std::size_t d = 0; d < c; ++d) value[d] += w * field[c * n + d];
    }
  }
  // One rank evaluates each marker and the others hold exact zeros: the sum is exact.
  if (!marker_values.empty())
    VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, marker_values.data(),
                               static_cast<int>(marker_values.size()), MPI_DOUBLE, MPI_SUM,
                               mesh_->comm.get()));
}

namespace {
// Eigen::Vector3d is three packed doubles, so a span of them is a node-major span of doubles.
static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
std::span<double> flat(std::span<Eigen::Vector3d> v) {
  return {reinterpret_cast<double*>(v.data()), 3 * v.size()};
}
std::span<const double> flat(std::span<const Eigen::Vector3d> v) {
  return {reinterpret_cast<const double*>(v.data()), 3 * v.size()};
}
}  // namespace

void DiracTransfer::spread(std::span<const Eigen::Vector3d> marker_force,
                           std::span<Eigen::Vector3d> density) {
  spread(flat(marker_force), 3, flat(density));
}

void DiracTransfer::interpolate(std::span<Eigen::Vector3d> field,
                                std::span<Eigen::Vector3d> marker_values) {
  interpolate(flat(field), 3, flat(marker_values));
}

}  // namespace valsalva::ibm
