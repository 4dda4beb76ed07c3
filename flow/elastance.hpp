// Time-varying elastance E(t) of a lumped ventricle, Pa/m^3 (p_lv = E(t) (V - V0), the
// varying-elastance model of Suga, Sagawa & Shoukas, Circ. Res. 32, 314-322, 1973):
//   raised_cosine  E = E_min + (E_max - E_min) e(t mod T),
//                  e(s) = (1 - cos(2 pi s / T_s)) / 2 for s < T_s (systole), 0 after,
//                  a smooth (C^1) one-hump activation peaking at T_s / 2; simpler than the
//                  double-Hill curve of Stergiopulos, Meister & Westerhof (Am. J. Physiol. 270,
//                  H2050-H2059, 1996) and, like it, E_min through diastole;
//   table          a periodic CSV table of (t, E) rows (flow::Waveform, io/waveform_table.hpp).
#pragma once

#include <cmath>
#include <numbers>

#include "flow/inflow_waveform.hpp"

namespace valsalva::flow {

struct Elastance {
  bool tabulated = false;
  double minimum = 0, maximum = 0;   // Pa/m^3 (raised_cosine)
  double period = 1, systole = 0.3;  // s (raised_cosine)
  Waveform table;                    // tabulated: (t, E)

  double operator()(double t) const {
    if (tabulated) return table(t);
    const double s = t - period * std::floor(t / period);
    const double e = s < systole ? 0.5 * (1 - std::cos(2 * std::numbers::pi * s / systole)) : 0.0;
    return minimum + (maximum - minimum) * e;
  }
};

}  // namespace valsalva::flow
