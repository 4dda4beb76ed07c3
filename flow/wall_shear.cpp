// Wall shear stress, TAWSS and OSI; see wall_shear.hpp.
#include "flow/wall_shear.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace valsalva::flow {

std::vector<Eigen::Vector3d> wall_shear_stress(const std::vector<WallLoad>& loads) {
  std::vector<Eigen::Vector3d> tau;
  tau.reserve(loads.size());
  for (const auto& l : loads) {
    const double a = l.area.norm();
    if (!(a > 0)) {
      tau.emplace_back(Eigen::Vector3d::Zero());
      continue;
    }
    const Eigen::Vector3d n = l.area / a;
    tau.push_back((l.force - l.force.dot(n) * n) / a);
  }
  return tau;
}

void WallShearStatistics::add(const std::vector<Eigen::Vector3d>& start,
                              const std::vector<Eigen::Vector3d>& end, double dt) {
  if (sum_tau_.empty() && duration_ == 0) {
    sum_tau_.assign(end.size(), Eigen::Vector3d::Zero());
    sum_abs_.assign(end.size(), 0.0);
  }
  if (start.size() != sum_tau_.size() || end.size() != sum_tau_.size())
    throw std::invalid_argument("flow::WallShearStatistics::add: " + std::to_string(start.size()) +
                                " and " + std::to_string(end.size()) +
                                " wall nodes, the statistics hold " +
                                std::to_string(sum_tau_.size()));
  if (!(dt > 0)) throw std::invalid_argument("flow::WallShearStatistics::add: dt must be > 0");
  for (std::size_t i = 0; i < end.size(); ++i) {
    sum_tau_[i] += dt / 2 * (start[i] + end[i]);
    sum_abs_[i] += dt / 2 * (start[i].norm() + end[i].norm());
  }
  duration_ += dt;
}

std::vector<double> WallShearStatistics::tawss() const {
  std::vector<double> out(sum_abs_.size(), 0.0);
  if (duration_ > 0)
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = sum_abs_[i] / duration_;
  return out;
}

std::vector<double> WallShearStatistics::osi() const {
  std::vector<double> out(sum_abs_.size(), 0.0);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (sum_abs_[i] > 0) out[i] = 0.5 * (1 - sum_tau_[i].norm() / sum_abs_[i]);
  return out;
}

std::vector<double> WallShearStatistics::rrt() const {
  std::vector<double> out(sum_abs_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double mean = sum_tau_[i].norm();  // |int tau_w dt|
    if (duration_ > 0 && mean > 0) out[i] = duration_ / mean;
  }
  return out;
}

std::vector<double> WallShearStatistics::state() const {
  std::vector<double> s;
  s.reserve(4 * sum_abs_.size() + 1);
  for (std::size_t i = 0; i < sum_abs_.size(); ++i) {
    s.insert(s.end(), {sum_tau_[i].x(), sum_tau_[i].y(), sum_tau_[i].z(), sum_abs_[i]});
  }
  s.push_back(duration_);
  return s;
}

void WallShearStatistics::restore(const std::vector<double>& s) {
  if (s.empty() || (s.size() - 1) % 4 != 0)
    throw std::invalid_argument("flow::WallShearStatistics::restore: " + std::to_string(s.size()) +
                                " values is not 4 per node + 1");
  const std::size_t n = (s.size() - 1) / 4;
  sum_tau_.resize(n);
  sum_abs_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    sum_tau_[i] = Eigen::Vector3d(s[4 * i], s[4 * i + 1], s[4 * i + 2]);
    sum_abs_[i] = s[4 * i + 3];
  }
  duration_ = s.back();
}

}  // namespace valsalva::flow
