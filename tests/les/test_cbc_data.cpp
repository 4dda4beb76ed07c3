// Comte-Bellot & Corrsin spectra reader (les/cbc_data.hpp) against the rules in
// refdata/cbc_decaying_turbulence/SOURCE.txt.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "les/cbc_data.hpp"

using namespace valsalva::les;

namespace {
const std::string dir =
    std::string(VALSALVA_SOURCE_DIR) + "/validation/refdata/cbc_decaying_turbulence/";

// Plain numeric table: rows of numbers (other transcriptions, for the cross-check).
std::vector<std::vector<double>> numeric_rows(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::vector<double> r;
    for (double x; ls >> x;) r.push_back(x);
    if (!r.empty()) rows.push_back(r);
  }
  return rows;
}

// Measured values keyed by (station index, k in cm^-1 * 100), in cm units.
using Measured = std::map<std::pair<int, long>, double>;
Measured from_reader(const CbcSpectra& c) {
  Measured m;
  for (int s = 0; s < 3; ++s)
    for (std::size_t i = 0; i < c.stations[s].k.size(); ++i)
      m[{s, std::lround(c.stations[s].k[i])}] = c.stations[s].E[i] * 1e6;  // k [1/m] = 100 k[1/cm]
  return m;
}
}  // namespace

TEST_CASE("CBC table 3: values, units and missing entries") {
  const CbcSpectra c = read_cbc_table3(dir + "PHiLiP_cbc_experiment_table3.txt");
  const auto& s42 = c.at(42);
  const auto& s98 = c.at(98);
  const auto& s171 = c.at(171);
  // 20 table rows; '-' at k = 0.15 (42, 98) and k = 17.5, 20 (171): 56 measured values.
  CHECK(s42.k.size() == 19);
  CHECK(s98.k.size() == 19);
  CHECK(s171.k.size() == 18);
  CHECK(s42.k.front() == doctest::Approx(20.0));    // 0.20 cm^-1, not the missing 0.15
  CHECK(s171.k.front() == doctest::Approx(15.0));   // 0.15 cm^-1 is measured at 171
  CHECK(s171.k.back() == doctest::Approx(1500.0));  // 15 cm^-1; 17.5 and 20 are missing
  CHECK(s42.k.back() == doctest::Approx(2000.0));
  // A few values, SI (E [cm^3/s^2] * 1e-6).
  CHECK(s42.E[0] == doctest::Approx(129e-6).epsilon(1e-12));
  CHECK(s42.E[4] == doctest::Approx(457e-6).epsilon(1e-12));    // k = 0.5
  CHECK(s98.E[6] == doctest::Approx(79.2e-6).epsilon(1e-12));   // k = 1.0
  CHECK(s171.E[0] == doctest::Approx(49.7e-6).epsilon(1e-12));  // k = 0.15
  CHECK(s171.E.back() == doctest::Approx(1.41e-8).epsilon(1e-12));
  // As an interpolation table (log-log): exact at the nodes.
  const SpectrumTable t = s98.table(Extrapolation::none);
  CHECK(t(100.0) == doctest::Approx(79.2e-6).epsilon(1e-12));
  CHECK_THROWS_AS(t(10.0), std::out_of_range);
  CHECK_THROWS_AS(c.at(50), std::out_of_range);
  CHECK(cbc_mesh_size == 0.0508);
  CHECK(cbc_u0 == 10.0);
}

TEST_CASE("CBC: the 56 measured values agree with the other transcriptions, padding ignored") {
  const Measured ref = from_reader(read_cbc_table3(dir + "PHiLiP_cbc_experiment_table3.txt"));
  CHECK(ref.size() == 56);

  // FDS: missing entries encoded as 0.00E+00 and 0.01E-03 (SOURCE.txt).
  Measured fds;
  for (const auto& r : numeric_rows(dir + "FDS_cbcdata.txt")) {
    REQUIRE(r.size() == 4);
    for (int s = 0; s < 3; ++s)
      if (r[s + 1] != 0.0 && r[s + 1] != 0.01e-3) fds[{s, std::lround(r[0] * 100)}] = r[s + 1];
  }
  // TurboGenPY: rows k = 0.11 and k >= 30 are padding; at k = 0.15 only 49.7 (171) is measured.
  Measured tg;
  for (const auto& r : numeric_rows(dir + "TurboGenPY_cbc_spectrum.txt")) {
    REQUIRE(r.size() == 4);
    if (r[0] < 0.12 || r[0] >= 30.0) continue;
    for (int s = 0; s < 3; ++s) {
      if (r[0] == 0.15 && s != 2) continue;
      if (r[s + 1] == 0.0) continue;  // 17.5, 20 at 171
      tg[{s, std::lround(r[0] * 100)}] = r[s + 1];
    }
  }
  CHECK(fds.size() == 56);
  CHECK(tg.size() == 56);
  int agree = 0;
  for (const auto& [key, e] : ref) {
    const bool f = fds.count(key) && std::abs(fds[key] - e) <= 1e-12 * e;
    const bool t = tg.count(key) && std::abs(tg[key] - e) <= 1e-12 * e;
    agree += f && t;
  }
  CHECK(agree == 56);
}

TEST_CASE("CBC reader: malformed input names file and line") {
  const std::string path = "les_cbc_bad_table.txt";
  {
    std::ofstream out(path);
    out << "k  t=42 t=98 t=171\n0.20 1.29E+2 1.06E+2 9.20E+1\n0.25 2.30E+2 x 1.20E+2\n";
  }
  std::string msg;
  try {
    read_cbc_table3(path);
  } catch (const std::runtime_error& e) {
    msg = e.what();
  }
  CHECK(msg.find(path + ":3:") != std::string::npos);
  CHECK(msg.find("'x'") != std::string::npos);
  std::remove(path.c_str());
  CHECK_THROWS_AS(read_cbc_table3("does/not/exist.txt"), std::runtime_error);
  // A typo in the first data row is not taken for a header; inf is not a value.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"k  t=42 t=98 t=171\n0.2O 1.29E+2 1.06E+2 9.20E+1\n0.25 2.30E+2 1.96E+2 1.20E+2\n",
       ":2: expected a finite wavenumber, got '0.2O'"},
      {"k  t=42 t=98 t=171\n0.20 1.29E+2 inf 9.20E+1\n0.25 2.30E+2 1.96E+2 1.20E+2\n",
       ":2: E at tU0/M = 98: 'inf'"},
  };
  for (const auto& [text, expected] : bad) {
    {
      std::ofstream out(path);
      out << text;
    }
    std::string why;
    try {
      read_cbc_table3(path);
    } catch (const std::runtime_error& e) {
      why = e.what();
    }
    CAPTURE(why);
    CHECK(why.find(path + expected) != std::string::npos);
  }
  std::remove(path.c_str());
}
