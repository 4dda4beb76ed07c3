// Generalised-Newtonian viscosity laws; see viscosity_model.hpp.
#include "flow/viscosity_model.hpp"

#include <fmt/format.h>

#include <cmath>

namespace valsalva::flow {

std::optional<ViscosityModelProblem> viscosity_model_problem(const ViscosityModel& m) {
  auto bad = [](const char* parameter, std::string message, std::string accepted) {
    return std::optional<ViscosityModelProblem>(
        ViscosityModelProblem{parameter, std::move(message), std::move(accepted)});
  };
  auto nonnegative = [&](const char* parameter,
                         double value) -> std::optional<ViscosityModelProblem> {
    if (std::isfinite(value) && value >= 0) return std::nullopt;
    return bad(parameter, fmt::format("{:g} must be a finite number >= 0", value), ">= 0");
  };
  auto positive = [&](const char* parameter, double value) -> std::optional<ViscosityModelProblem> {
    if (std::isfinite(value) && value > 0) return std::nullopt;
    return bad(parameter, fmt::format("{:g} must be a finite number > 0", value), "> 0");
  };
  std::optional<ViscosityModelProblem> p;
  switch (m.law) {
    case ViscosityLaw::newtonian:
      return nonnegative("mu", m.mu);
    case ViscosityLaw::carreau_yasuda:
      if ((p = positive("mu_0", m.mu_0)) || (p = nonnegative("mu_inf", m.mu_inf)) ||
          (p = nonnegative("lambda", m.lambda)) || (p = positive("a", m.a)) ||
          (p = positive("n", m.n)))
        return p;
      if (m.mu_0 < m.mu_inf)
        return bad("mu_0",
                   fmt::format("{:g} Pa s is below mu_inf = {:g} Pa s: the zero-shear "
                               "viscosity of Carreau-Yasuda must be >= the "
                               "infinite-shear one",
                               m.mu_0, m.mu_inf),
                   fmt::format(">= mu_inf = {:g} Pa s", m.mu_inf));
      return std::nullopt;
    case ViscosityLaw::casson:
      if ((p = nonnegative("yield_stress", m.yield_stress)) ||
          (p = positive("plastic_viscosity", m.plastic_viscosity)) ||
          (p = nonnegative("regularisation", m.regularisation)))
        return p;
      if (m.yield_stress > 0 && m.regularisation == 0)
        return bad("regularisation",
                   fmt::format("0 with a yield stress of {:g} Pa: the unregularised Casson "
                               "viscosity is infinite at rest; give Papanastasiou's m > 0 (s)",
                               m.yield_stress),
                   "> 0 s with a yield stress > 0");
      return std::nullopt;
    case ViscosityLaw::power_law:
      if ((p = positive("consistency", m.consistency)) || (p = positive("n", m.n)) ||
          (p = positive("shear_rate_min", m.shear_rate_min)))
        return p;
      return std::nullopt;
  }
  return std::nullopt;
}

double apparent_viscosity(const ViscosityModel& m, double gamma_dot) {
  switch (m.law) {
    case ViscosityLaw::newtonian:
      return m.mu;
    case ViscosityLaw::carreau_yasuda:
      return m.mu_inf + (m.mu_0 - m.mu_inf) *
                            std::pow(1 + std::pow(m.lambda * gamma_dot, m.a), (m.n - 1) / m.a);
    case ViscosityLaw::casson: {
      // tau_y (1 - e^{-m g}) / g, with its limit tau_y m at g = 0 (expm1: no cancellation).
      const double x = m.regularisation * gamma_dot;
      const double yield_term =
          x > 0 ? -m.yield_stress * std::expm1(-x) / gamma_dot : m.yield_stress * m.regularisation;
      const double root = std::sqrt(m.plastic_viscosity) + std::sqrt(yield_term);
      return root * root;
    }
    case ViscosityLaw::power_law:
      return m.consistency * std::pow(std::max(gamma_dot, m.shear_rate_min), m.n - 1);
  }
  return m.mu;
}

double lowest_viscosity(const ViscosityModel& m) {
  switch (m.law) {
    case ViscosityLaw::newtonian:
      return m.mu;
    case ViscosityLaw::carreau_yasuda:  // monotone in gamma_dot, mu_0 at rest
      return m.n < 1 ? m.mu_inf : m.mu_0;
    case ViscosityLaw::casson:  // decreasing towards mu_p
      return m.plastic_viscosity;
    case ViscosityLaw::power_law:  // K gamma^(n - 1) above the floor
      return m.n < 1 ? 0.0 : m.consistency * std::pow(m.shear_rate_min, m.n - 1);
  }
  return m.mu;
}

double viscosity_cap(const ViscosityModel& m) {
  if (m.law != ViscosityLaw::power_law || m.n >= 1) return 0.0;
  return m.consistency * std::pow(m.shear_rate_min, m.n - 1);
}

std::string viscosity_law_name(ViscosityLaw law) {
  switch (law) {
    case ViscosityLaw::newtonian:
      return "newtonian";
    case ViscosityLaw::carreau_yasuda:
      return "carreau_yasuda";
    case ViscosityLaw::casson:
      return "casson";
    case ViscosityLaw::power_law:
      return "power_law";
  }
  return "?";
}

}  // namespace valsalva::flow
