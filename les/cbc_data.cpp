#include "les/cbc_data.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace valsalva::les {

namespace {
constexpr double per_cm = 100.0;     // 1/cm -> 1/m
constexpr double cm3_per_s2 = 1e-6;  // cm^3/s^2 -> m^3/s^2

// A finite number spelled as the whole token (from_chars also reads "inf" and "nan").
bool parse_number(const std::string& token, double& value) {
  const char* end = token.data() + token.size();
  const auto r = std::from_chars(token.data(), end, value);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(value);
}

bool any_number(const std::vector<std::string>& tokens) {
  double v = 0;
  for (const auto& t : tokens)
    if (parse_number(t, v)) return true;
  return false;
}
}  // namespace

SpectrumTable CbcStation::table(Extrapolation extrapolation) const {
  return SpectrumTable(k, E, extrapolation,
                       fmt::format("Comte-Bellot & Corrsin spectrum at tU0/M = {}", t_u0_over_m));
}

const CbcStation& CbcSpectra::at(int t_u0_over_m) const {
  for (const auto& s : stations)
    if (s.t_u0_over_m == t_u0_over_m) return s;
  throw std::out_of_range(
      fmt::format("{}: no station tU0/M = {}; available: 42, 98, 171", source, t_u0_over_m));
}

CbcSpectra read_cbc_table3(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot open the CBC spectrum table", path));
  CbcSpectra out;
  out.source = path;
  for (int s = 0; s < 3; ++s) out.stations[s].t_u0_over_m = cbc_stations[s];
  std::string line;
  int line_no = 0;
  bool in_data = false;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    std::vector<std::string> tok;
    for (std::string t; ls >> t;) tok.push_back(t);
    if (tok.empty()) continue;
    double k = 0.0;
    if (!parse_number(tok[0], k)) {
      // A header line holds no number at all (recognised, not guessed): a data row with a typo
      // in its wavenumber is an error, not a header.
      if (in_data || any_number(tok))
        throw std::runtime_error(
            fmt::format("{}:{}: expected a finite wavenumber, got '{}'", path, line_no, tok[0]));
      continue;
    }
    in_data = true;
    if (tok.size() != 4)
      throw std::runtime_error(
          fmt::format("{}:{}: expected 4 columns (k, E at tU0/M = 42, 98, 171), got {}", path,
                      line_no, tok.size()));
    for (int s = 0; s < 3; ++s) {
      const std::string& t = tok[s + 1];
      if (t == "-") continue;  // no entry in the published table
      double e = 0.0;
      if (!parse_number(t, e) || !(e > 0.0))
        throw std::runtime_error(
            fmt::format("{}:{}: E at tU0/M = {}: '{}' is neither '-' nor a positive number", path,
                        line_no, cbc_stations[s], t));
      auto& st = out.stations[s];
      if (!st.k.empty() && !(k * per_cm > st.k.back()))
        throw std::runtime_error(fmt::format("{}:{}: k = {} does not increase", path, line_no, k));
      st.k.push_back(k * per_cm);
      st.E.push_back(e * cm3_per_s2);
    }
  }
  for (const auto& st : out.stations)
    if (st.k.size() < 2)
      throw std::runtime_error(
          fmt::format("{}: fewer than 2 values for tU0/M = {}", path, st.t_u0_over_m));
  return out;
}

}  // namespace valsalva::les
