// Forces of one immersed solid; see immersed_body.hpp.
#include "ibm/immersed_body.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace valsalva::ibm {

using structure::Mat3;
using structure::Vec3;

Eigen::VectorXd lumped_nodal_volume(const structure::SolidMesh& mesh) {
  const int nen = mesh.nodes_per_element();
  const auto rule = structure::gauss_hex(structure::default_gauss(mesh.order));
  std::vector<double> N(nen), dN(3 * nen);
  Eigen::VectorXd volume = Eigen::VectorXd::Zero(mesh.num_nodes());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* en = mesh.element_nodes(e);
    for (int g = 0; g < rule.size(); ++g) {
      structure::hex_shape(mesh.order, rule.points[g], N, dN);
      Mat3 J = Mat3::Zero();  // dX/dxi
      for (int a = 0; a < nen; ++a)
        for (int k = 0; k < 3; ++k) J.col(k) += mesh.X.col(en[a]) * dN[3 * a + k];
      const double w = rule.weights[g] * J.determinant();
      for (int a = 0; a < nen; ++a) volume[en[a]] += w * N[a];
    }
  }
  return volume;
}

ImmersedBody::ImmersedBody(const structure::SolidMesh& mesh, const structure::Material& material,
                           BodySpec spec)
    : forces_(mesh, material), spec_(std::move(spec)) {
  for (const auto& name : spec_.clamped_sets) {
    const auto& set = mesh.node_set(name);  // throws naming the set when it does not exist
    clamped_.insert(clamped_.end(), set.begin(), set.end());
  }
  std::sort(clamped_.begin(), clamped_.end());
  clamped_.erase(std::unique(clamped_.begin(), clamped_.end()), clamped_.end());
  if (spec_.clamp == Clamp::fixed) fixed_ = clamped_;
  if (!clamped_.empty() && spec_.clamp == Clamp::tether &&
      !(spec_.tether_stiffness > 0 && std::isfinite(spec_.tether_stiffness)))
    throw std::invalid_argument(
        fmt::format("ibm::ImmersedBody '{}': clamped node sets need a positive tether stiffness "
                    "[N/m] (got {})",
                    spec_.name, spec_.tether_stiffness));
  nodal_volume_ = lumped_nodal_volume(mesh);
  if (!spec_.contact.empty() || !spec_.obstacles.empty()) {
    try {
      contact_ = std::make_unique<structure::Contact>(mesh, material, spec_.contact,
                                                      spec_.obstacles, spec_.contact_options);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("ibm::ImmersedBody '{}': {}", spec_.name, e.what()));
    }
    obstacle_stiffness_ = contact_->obstacle_stiffness();
  }
  const int nen = mesh.nodes_per_element();
  for (int a = 0; a < nen; ++a)
    for (int b = a + 1; b < nen; ++b) {
      const Vec3 d = structure::hex_reference_node(mesh.order, a) -
                     structure::hex_reference_node(mesh.order, b);
      // One lattice step along one reference axis: 2/p in reference units.
      const double step = 2.0 / static_cast<int>(mesh.order);
      if (std::abs(d.norm() - step) < 1e-12) neighbour_pairs_.push_back({a, b});
    }
}

double ImmersedBody::forces(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                            Eigen::Ref<Eigen::Matrix3Xd> f) const {
  const double min_det = forces_.internal_forces(x, f);
  const auto& X = mesh().X;
  if (spec_.clamp == Clamp::tether)
    for (int a : clamped_) f.col(a) -= spec_.tether_stiffness * (x.col(a) - X.col(a));
  // min_det is the same on every process (the internal forces are whole on each), so either all
  // or none take part in the sum.
  if (contact_ && min_det > 0) {
    if (share_.parts == 1) {
      contact_->add_forces(x, f);
    } else {
      shared_contact_force_.setZero(3, x.cols());
      contact_->add_forces(x, shared_contact_force_, nullptr, share_);
      sum_shares_(std::span<double>(shared_contact_force_.data(), shared_contact_force_.size()));
      f += shared_contact_force_;
    }
  }
  return min_det;
}

void ImmersedBody::share_contact(structure::ContactShare share,
                                 std::function<void(std::span<double>)> sum) {
  if (share.parts < 1 || share.part < 0 || share.part >= share.parts || (share.parts > 1 && !sum))
    throw std::invalid_argument(fmt::format(
        "ibm::ImmersedBody '{}': contact share {} of {} (needs 0 <= part < parts and a sum when "
        "parts > 1)",
        spec_.name, share.part, share.parts));
  share_ = share;
  sum_shares_ = std::move(sum);
}

structure::ContactSummary ImmersedBody::contact_summary(
    const Eigen::Ref<const Eigen::Matrix3Xd>& x) const {
  return contact_ ? contact_->summary(x) : structure::ContactSummary{};
}

Eigen::Vector3d ImmersedBody::tether_force(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const {
  Vec3 total = Vec3::Zero();
  if (spec_.clamp == Clamp::fixed) return total;
  for (int a : clamped_) total -= spec_.tether_stiffness * (x.col(a) - mesh().X.col(a));
  return total;
}

void ImmersedBody::stiffness(const Eigen::Matrix3Xd& x, Eigen::SparseMatrix<double>& K) const {
  Eigen::Matrix3Xd f(3, num_nodes());
  forces_.assemble(x, f, K);
  if (spec_.clamp == Clamp::tether)
    for (int a : clamped_)
      for (int i = 0; i < 3; ++i) K.coeffRef(3 * a + i, 3 * a + i) += spec_.tether_stiffness;
  if (!contact_) return;
  std::vector<Eigen::Triplet<double>> tangent;
  contact_->add_forces(x, f, &tangent);
  Eigen::SparseMatrix<double> Kc(K.rows(), K.cols());
  Kc.setFromTriplets(tangent.begin(), tangent.end());
  K += Kc;
  for (int a = 0; a < num_nodes(); ++a)
    if (obstacle_stiffness_[a] > 0)
      for (int i = 0; i < 3; ++i) K.coeffRef(3 * a + i, 3 * a + i) += obstacle_stiffness_[a];
}

double ImmersedBody::max_marker_spacing(const Eigen::Matrix3Xd& x) const {
  double worst = 0;
  for (int e = 0; e < mesh().num_elements(); ++e) {
    const int* en = mesh().element_nodes(e);
    for (const auto& [a, b] : neighbour_pairs_)
      worst = std::max(worst, (x.col(en[a]) - x.col(en[b])).norm());
  }
  return worst;
}

}  // namespace valsalva::ibm
