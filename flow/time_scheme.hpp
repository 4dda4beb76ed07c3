// The explicit 4-stage Runge-Kutta schemes of the projection's predictor (time.scheme), both in
// the form "each stage from the previous one only" (a diagonal Butcher tableau below its
// diagonal), applied to dv/dt = R(v) - grad(p^n)/rho:
//   w_0 = v^n,  w_k = v^n + c_k dt R(w_{k-1})  (k = 1..3, w_k stands at t^n + c_k dt),
//   v* = v^n + dt sum_k b_k R(w_k).
// rk4_jameson  c = 0, 1/4, 1/3, 1/2;   b = 0, 0, 0, 1   (the low-storage form of Jameson,
//              Schmidt & Turkel, AIAA 81-1259, 1981, used by YALES2): v* = w_4 with c_4 = 1.
//              4th order for linear autonomous R only; 2nd order on the nonlinear equations.
// rk4_classic  c = 0, 1/2, 1/2, 1;     b = 1/6, 1/3, 1/3, 1/6  (Kutta, 1901): 4th order for
//              any smooth R. One more stored field (the weighted sum of the R(w_k)).
// Both have the stability polynomial 1 + z + z^2/2 + z^3/6 + z^4/24, so the time-step limits
// of flow/run_diagnostics.hpp hold for both.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace valsalva::flow {

enum class TimeScheme { rk4_jameson, rk4_classic };

struct RungeKuttaTableau {
  std::array<double, 4> c;  // stage k evaluates R at t^n + c_k dt; c_0 = 0
  std::array<double, 4> b;  // weights of R(w_k) in v*
  // v* needs only R(w_3) (b = 0, 0, 0, 1): nothing is accumulated and v* is the last stage.
  bool last_stage_only() const { return b[0] == 0 && b[1] == 0 && b[2] == 0 && b[3] == 1; }
  // The coefficient of R(w_k) in the update it starts: c_{k+1} for k < 3, 1 for the last.
  double update_coefficient(int k) const { return k < 3 ? c[k + 1] : 1.0; }
};

RungeKuttaTableau tableau(TimeScheme scheme);

// The scene names: "rk4_jameson", "rk4_classic".
const std::vector<std::string>& time_scheme_names();
std::string time_scheme_name(TimeScheme scheme);
// std::invalid_argument naming the value and the accepted names for an unknown name.
TimeScheme parse_time_scheme(std::string_view name);

}  // namespace valsalva::flow
