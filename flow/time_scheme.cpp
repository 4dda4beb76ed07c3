// Runge-Kutta tableaus of the predictor; see time_scheme.hpp.
#include "flow/time_scheme.hpp"

#include <stdexcept>

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

const std::vector<std::string>& time_scheme_names() {
  static const std::vector<std::string> names{"rk4_jameson", "rk4_classic"};
  return names;
}

std::string time_scheme_name(TimeScheme scheme) {
  return time_scheme_names()[static_cast<std::size_t>(scheme)];
}

TimeScheme parse_time_scheme(std::string_view name) {
  const auto& names = time_scheme_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<TimeScheme>(i);
  std::string accepted;
  for (const auto& n : names) accepted += (accepted.empty() ? "" : ", ") + n;
  throw std::invalid_argument("flow: time scheme '" + std::string(name) + "' is not one of " +
                              accepted);
}

}  // namespace valsalva::flow
