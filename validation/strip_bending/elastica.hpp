// Reference for large deflections of a cantilever under a dead transverse tip load: the
// inextensible elastica theta'' = -alpha cos(theta) on s in [0, 1] (s = arc length / L,
// alpha = P L^2 / EI), theta(0) = 0, theta'(1) = 0, solved by shooting on theta'(0) with RK4
// and bisection (Bisshopp & Drucker, Q. Appl. Math. 3:272, 1945, tabulate the same problem).
#pragma once

namespace valsalva::validation {

struct ElasticaTip {
  double deflection;  // transverse tip displacement / L
  double shortening;  // (L - horizontal tip position) / L
  double theta_tip;   // tip rotation [rad]
};

ElasticaTip elastica_tip(double alpha, int steps = 4000);

}  // namespace valsalva::validation
