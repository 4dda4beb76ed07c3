// A tabulated energy spectrum E(k), interpolated linearly in log k - log E (power law between
// points), as used to prescribe initial spectra (e.g. Comte-Bellot & Corrsin 1971).
#pragma once

#include <string>
#include <vector>

namespace valsalva::les {

enum class Extrapolation {
  none,      // a k outside [k_first, k_last] is an error
  power_law  // continue the first / last segment's power law
};

class SpectrumTable {
 public:
  // k strictly increasing and > 0, E > 0, at least two points; `source` names the data in errors.
  SpectrumTable(std::vector<double> k, std::vector<double> E, Extrapolation extrapolation,
                std::string source = "<table>");
  double operator()(double k) const;
  const std::vector<double>& k() const { return k_; }
  const std::vector<double>& E() const { return E_; }

 private:
  std::vector<double> k_, E_, logk_, logE_;
  Extrapolation extrapolation_;
  std::string source_;
};

// Exact integral of k^p E(k) over the table's range [k_first, k_last] (power law per segment).
double table_moment(const SpectrumTable& E, double p);

// Large-scale quantities of an isotropic spectrum over the table's range: kinetic energy
// K = int E dk, u' = sqrt(2K/3), longitudinal integral scale L11 = pi / (2 u'^2) int E / k dk
// (Pope, Turbulent Flows, eq. 6.213) and the large-eddy turnover time L11 / u'.
struct LargeScales {
  double energy = 0, u_rms = 0, integral_length = 0, turnover_time = 0;
};
LargeScales large_scales(const SpectrumTable& E);

}  // namespace valsalva::les
