// io/uniform_sampling: uniform times are recognised despite 17-digit printing, jittered ones are
// not; linear interpolation reproduces a linear signal to round-off and hits the end points;
// non-increasing times and too few samples are refused naming the sample.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "analysis/uniform_sampling.hpp"

using namespace valsalva;

TEST_CASE("uniform sampling: detection and linear resampling") {
  // t = k dt accumulated as a run does (t += dt): round-off only, so uniform.
  std::vector<double> t(1000);
  for (std::size_t k = 1; k < t.size(); ++k) t[k] = t[k - 1] + 1e-4;
  const auto u = analysis::check_sampling(t, "series");
  CHECK(u.uniform);
  CHECK(u.dt_mean == doctest::Approx(1e-4).epsilon(1e-12));

  // A run whose dt changed by 1% half-way: not uniform.
  std::vector<double> j(t);
  for (std::size_t k = 500; k < j.size(); ++k) j[k] = j[k - 1] + 1.01e-4;
  const auto s = analysis::check_sampling(j, "series");
  CHECK_FALSE(s.uniform);
  CHECK(s.dt_min == doctest::Approx(1e-4).epsilon(1e-9));
  CHECK(s.dt_max == doctest::Approx(1.01e-4).epsilon(1e-9));

  // Linear signal: interpolation is exact (round-off, values of order 1).
  std::vector<double> v;
  for (double x : j) v.push_back(3 - 2 * x);
  const auto r = analysis::resample_uniform(j, v, 777);
  REQUIRE(r.size() == 777);
  double worst = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double tk = j.front() + double(k) * (j.back() - j.front()) / 776.0;
    worst = std::max(worst, std::abs(r[k] - (3 - 2 * tk)));
  }
  CHECK(worst < 1e-14);
  CHECK(r.front() == v.front());
  CHECK(r.back() == v.back());
}

TEST_CASE("uniform sampling: bad series are refused") {
  CHECK_THROWS_WITH(analysis::check_sampling(std::vector<double>{0.0}, "probes.csv"),
                    doctest::Contains("probes.csv: 1 time samples, at least 2 needed"));
  CHECK_THROWS_WITH(analysis::check_sampling(std::vector<double>{0.0, 0.1, 0.1}, "probes.csv"),
                    doctest::Contains("not strictly increasing at sample 2"));
  CHECK_THROWS_WITH(analysis::check_sampling(std::vector<double>{0.0, NAN, 0.3}, "probes.csv"),
                    doctest::Contains("not strictly increasing at sample 1"));
  CHECK_THROWS_WITH(
      analysis::resample_uniform(std::vector<double>{0, 1}, std::vector<double>{0}, 4),
      doctest::Contains("2 times, 1 values"));
}
