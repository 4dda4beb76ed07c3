// Runge-Kutta tableaus of the predictor; see time_scheme.hpp.
#include "flow/time_scheme.hpp"

#include <stdexcept>

#include "core/enum_names.hpp"

namespace valsalva::flow {

RungeKuttaTableau tableau(TimeScheme scheme) {
  switch (scheme) {
    case TimeScheme::rk4_jameson:
      return {{0.0, 1.0 / 4, 1.0 / 3, 1.0 / 2}, {0.0, 0.0, 0.0, 1.0}};
    case TimeScheme::rk4_classic:
      return {{0.0, 1.0 / 2, 1.0 / 2, 1.0}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};
  }
  throw std::logic_error("flow::tableau: unknown time scheme");
}

constexpr core::EnumNames<TimeScheme, 2> kSchemes{{"rk4_jameson", "rk4_classic"},
                                                  "flow: time scheme"};

VALSALVA_ENUM_NAMES(TimeScheme, kSchemes, time_scheme_names, time_scheme_name, parse_time_scheme)

}  // namespace valsalva::flow
