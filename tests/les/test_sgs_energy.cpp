// Yoshizawa subgrid energy and the subgrid energy fraction against hand-computed values.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "les/sgs_energy.hpp"

using namespace valsalva;

TEST_CASE("Yoshizawa subgrid energy and fraction: hand-computed values") {
  // nu_sgs = 1e-4 m^2/s, Delta = 1 cm: sqrt(k_sgs) = 1e-4 / (0.094 * 0.01) = 0.106383 m/s,
  // k_sgs = 0.0113173 m^2/s^2; with k_res = 0.05: fraction 0.0113173 / 0.0613173 = 0.184570.
  CHECK(les::yoshizawa_sgs_energy(1e-4, 0.01) == doctest::Approx(0.0113173).epsilon(1e-5));
  CHECK(les::subgrid_energy_fraction(les::yoshizawa_sgs_energy(1e-4, 0.01), 0.05) ==
        doctest::Approx(0.184570).epsilon(1e-5));
  // Another constant: C_k = 0.1 gives k_sgs = (1e-4 / 1e-3)^2 = 0.01 exactly.
  CHECK(les::yoshizawa_sgs_energy(1e-4, 0.01, 0.1) == doctest::Approx(0.01).epsilon(1e-14));
  CHECK(les::subgrid_energy_fraction(0.0, 0.0) == 0.0);  // laminar at rest
  CHECK(les::subgrid_energy_fraction(0.0, 1.0) == 0.0);  // no model activity
  CHECK(les::subgrid_energy_fraction(1.0, 0.0) == 1.0);  // nothing resolved

  const std::vector<double> nu{1e-4, 0.0, 2e-4}, delta{0.01, 0.02, 0.01}, k{0.05, 0.3, 0.0};
  std::vector<double> out(3);
  les::subgrid_energy_fraction(nu, delta, k, out);
  CHECK(out[0] == doctest::Approx(0.184570).epsilon(1e-5));
  CHECK(out[1] == 0.0);
  CHECK(out[2] == 1.0);

  CHECK_THROWS_AS(les::yoshizawa_sgs_energy(-1e-6, 0.01), std::invalid_argument);
  CHECK_THROWS_AS(les::yoshizawa_sgs_energy(1e-6, 0.0), std::invalid_argument);
  std::vector<double> short_out(2);
  CHECK_THROWS_AS(les::subgrid_energy_fraction(nu, delta, k, short_out), std::invalid_argument);
}
