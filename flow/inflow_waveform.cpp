// Flow-rate waveforms and their CSV reader; see inflow_waveform.hpp.
#include "flow/inflow_waveform.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>

namespace valsalva::flow {

double Waveform::operator()(double time) const {
  switch (kind) {
    case Kind::constant:
      return mean;
    case Kind::sine:
      return mean + amplitude * std::sin(2 * std::numbers::pi * time / period + phase);
    case Kind::table: {
      const double span = t.back() - t.front();
      double s = std::fmod(time - t.front(), span);
      if (s < 0) s += span;
      s += t.front();
      const auto it = std::upper_bound(t.begin(), t.end(), s);
      const std::size_t k = std::clamp<std::size_t>(it - t.begin(), 1, t.size() - 1);
      const double w = (s - t[k - 1]) / (t[k] - t[k - 1]);
      return (1 - w) * q[k - 1] + w * q[k];
    }
  }
  return 0;
}

namespace {

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',' || c == ';' || c == ' ' || c == '\t' || c == '\r') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool parse_number(const std::string& s, double& x) {
  const auto res = std::from_chars(s.data(), s.data() + s.size(), x);
  return res.ec == std::errc() && res.ptr == s.data() + s.size() && std::isfinite(x);
}

}  // namespace

Waveform read_waveform_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw WaveformError(fmt::format("{}: cannot open the waveform file", file.string()));
  Waveform w;
  w.kind = Waveform::Kind::table;
  std::string line;
  int number = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++number;
    const auto fields = fields_of(line);
    if (fields.empty() || fields[0][0] == '#') continue;
    double t = 0, q = 0;
    if (header_allowed && !parse_number(fields[0], t)) {
      header_allowed = false;  // a header such as "t,Q"
      continue;
    }
    header_allowed = false;
    if (fields.size() != 2 || !parse_number(fields[0], t) || !parse_number(fields[1], q))
      throw WaveformError(
          fmt::format("{}:{}: expected two finite numbers 't, Q' (s, m^3/s), got '{}'",
                      file.string(), number, line));
    if (!w.t.empty() && !(t > w.t.back()))
      throw WaveformError(fmt::format("{}:{}: time {} is not after the previous row's {}",
                                      file.string(), number, t, w.t.back()));
    w.t.push_back(t);
    w.q.push_back(q);
  }
  if (w.t.size() < 2)
    throw WaveformError(
        fmt::format("{}:{}: a waveform table needs at least two rows (t, Q), found {}",
                    file.string(), number, w.t.size()));
  w.period = w.t.back() - w.t.front();
  w.mean = 0;
  for (std::size_t k = 1; k < w.t.size(); ++k)
    w.mean += 0.5 * (w.q[k] + w.q[k - 1]) * (w.t[k] - w.t[k - 1]) / w.period;
  return w;
}

}  // namespace valsalva::flow
