#include "analysis/section_flux.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "core/compensated_sum.hpp"

namespace valsalva::analysis {

SectionFlux::SectionFlux(const mesh::LocalMesh& local, SectionOptions options)
    : local_(&local), options_(std::move(options)) {
  const auto& o = options_;
  const std::string key = "section." + o.name;
  if (!(o.normal.norm() > 0))
    throw std::invalid_argument(fmt::format("{}.normal: the normal is zero", key));
  if (o.bound == SectionOptions::Bound::disc && !(o.radius > 0))
    throw std::invalid_argument(fmt::format("{}.radius: {} m is not positive", key, o.radius));
  const Eigen::Vector3d n = o.normal.normalized();
  auto within = [&](const Eigen::Vector3d& x) {
    switch (o.bound) {
      case SectionOptions::Bound::disc: {
        const Eigen::Vector3d r = x - o.point;
        return (r - r.dot(n) * n).norm() <= o.radius;
      }
      case SectionOptions::Bound::box:
        return (x.array() >= o.lo.array()).all() && (x.array() <= o.hi.array()).all();
      case SectionOptions::Bound::none:
        break;
    }
    return true;
  };
  double area = 0;
  for (int e = 0; e < local.num_owned_edges; ++e) {
    const auto [j, k] = local.edges[e];
    // The rank owning the end of lower global id counts the edge (it has the edge: the other
    // end is an owned node or a first-layer ghost there).
    const int first = local.global_id[j] < local.global_id[k] ? j : k;
    if (first >= local.num_owned) continue;
    // An edge across a periodic pair joins nodes whose stored positions are a period apart: it is
    // taken as one of its two images, (x_j, x_j + edge vector) or (x_k - edge vector, x_k),
    // whichever the plane cuts (a period holds several edges, so not both); taken at face value
    // it would count as cut by every plane between the stored positions.
    const Eigen::Vector3d& ev = local.edge_vector[e];
    Eigen::Vector3d xj = local.position[j], xk = local.position[k];
    auto side = [&](const Eigen::Vector3d& x) { return (x - o.point).dot(n) > 0; };
    if ((xk - xj - ev).norm() > 1e-6 * ev.norm()) {
      if (side(xj) != side(xj + ev))
        xk = xj + ev;
      else
        xj = xk - ev;
    }
    const double dj = (xj - o.point).dot(n);
    const double dk = (xk - o.point).dot(n);
    // Behind: d <= 0, in front: d > 0, so a node on the plane belongs to exactly one side.
    if ((dj > 0) == (dk > 0)) continue;
    const double t = dj / (dj - dk);
    if (!within(xj + t * (xk - xj))) continue;
    const double sign = dk > 0 ? 1.0 : -1.0;
    edges_.push_back(e);
    signs_.push_back(sign);
    area += sign * local.edge_normal[e].dot(n);
  }
  global_edges_ = local.comm.sum(static_cast<std::int64_t>(edges_.size()));
  area_ = local.comm.sum(area);
  if (global_edges_ == 0)
    throw std::runtime_error(fmt::format(
        "{}: the plane through ({}, {}, {}) m with normal ({}, {}, {}) cuts no mesh edge{}", key,
        o.point.x(), o.point.y(), o.point.z(), o.normal.x(), o.normal.y(), o.normal.z(),
        o.bound == SectionOptions::Bound::none ? "" : " within its bound"));
}

double SectionFlux::flux(const flow::EdgeField& face_flux) const {
  if (face_flux.size() != local_->edges.size())
    throw std::invalid_argument(fmt::format("section.{}: {} face fluxes for {} local edges",
                                            options_.name, face_flux.size(), local_->edges.size()));
  // Compensated: the cut's fluxes have both signs near walls and in recirculation.
  core::CompensatedSum q;
  for (std::size_t i = 0; i < edges_.size(); ++i) q.add(signs_[i] * face_flux[edges_[i]]);
  return local_->comm.sum(q.value());
}

}  // namespace valsalva::analysis
