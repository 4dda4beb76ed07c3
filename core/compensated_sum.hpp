// Neumaier's compensated summation: sums of 10^6 dual volumes keep ~1e-16 relative accuracy
// instead of drifting by n * eps, so volume identities can be checked at 1e-12.
#pragma once

#include <cmath>

namespace valsalva::core {

class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    compensation_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0, compensation_ = 0;
};

}  // namespace valsalva::core
