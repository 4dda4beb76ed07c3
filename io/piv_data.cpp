#include "io/piv_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <stdexcept>

namespace valsalva::io {

namespace {

enum Column { col_x, col_y, col_u, col_v, col_urms, col_vrms, col_valid, col_frame, num_columns };
const char* const column_names[] = {"x", "y", "u", "v", "u_rms", "v_rms", "valid"};
const char* const known_list = "x, y, u, v, u_rms, v_rms, valid";

struct Reader {
  std::string source;
  [[noreturn]] void fail(int line, const std::string& what) const {
    if (line > 0)
      throw std::runtime_error(fmt::format("PIV file '{}' line {}: {}", source, line, what));
    throw std::runtime_error(fmt::format("PIV file '{}': {}", source, what));
  }
};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r\"");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\"");
  return s.substr(b, e - b + 1);
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Parses a number; empty and "nan" give NaN. Returns false when `s` is not a number.
bool parse_number(const std::string& s, double& out) {
  if (s.empty()) {
    out = NAN;
    return true;
  }
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// Column index of a name, or -1 (frame keys handled by the caller).
int known_column(const std::string& name) {
  for (int c = 0; c < 7; ++c)
    if (name == column_names[c]) return c;
  return -1;
}

// Maps header names to columns; errors for unknown, duplicate or missing names.
std::array<int, num_columns> map_columns(const Reader& r, int line,
                                         const std::vector<std::string>& names, bool allow_frame,
                                         std::string& frame_key) {
  std::array<int, num_columns> at;
  at.fill(-1);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string n = lower(names[i]);
    int c = known_column(n);
    if (c < 0 && allow_frame && (n == "phase" || n == "time")) {
      if (at[col_frame] >= 0) r.fail(line, "both 'phase' and 'time' columns");
      c = col_frame;
      frame_key = n;
    }
    if (c < 0)
      r.fail(line, fmt::format("unknown {} '{}' (known: {}{})", allow_frame ? "column" : "variable",
                               names[i], known_list, allow_frame ? ", phase, time" : ""));
    if (at[c] >= 0) r.fail(line, fmt::format("'{}' appears twice", names[i]));
    at[c] = static_cast<int>(i);
  }
  for (int c : {col_x, col_y, col_u, col_v})
    if (at[c] < 0) r.fail(line, fmt::format("missing column '{}'", column_names[c]));
  if ((at[col_urms] >= 0) != (at[col_vrms] >= 0)) r.fail(line, "u_rms and v_rms come together");
  return at;
}

// Appends one point; `values` indexed by the file's columns.
void add_point(const Reader& r, int line, const std::array<int, num_columns>& at,
               const std::vector<double>& values, PivFrame& f) {
  auto get = [&](int c) { return at[c] >= 0 ? values[at[c]] : NAN; };
  if (!std::isfinite(get(col_x)) || !std::isfinite(get(col_y)))
    r.fail(line, "x and y must be finite numbers");
  f.x.push_back(get(col_x));
  f.y.push_back(get(col_y));
  f.u.push_back(get(col_u));
  f.v.push_back(get(col_v));
  bool ok = std::isfinite(get(col_u)) && std::isfinite(get(col_v));
  if (at[col_urms] >= 0) {
    f.u_rms.push_back(get(col_urms));
    f.v_rms.push_back(get(col_vrms));
    ok = ok && std::isfinite(get(col_urms)) && std::isfinite(get(col_vrms));
  }
  if (at[col_valid] >= 0) {
    const double flag = get(col_valid);
    if (flag != 0 && flag != 1) r.fail(line, fmt::format("valid = {} must be 0 or 1", flag));
    ok = ok && flag == 1;
  }
  f.valid.push_back(ok ? 1 : 0);
}

std::vector<std::string> split(const std::string& line, const std::string& separators) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (!quoted && separators.find(c) != std::string::npos) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  return out;
}

std::vector<double> parse_values(const Reader& r, int line, const std::vector<std::string>& cells,
                                 const std::vector<std::string>& names) {
  std::vector<double> values(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (!parse_number(cells[i], values[i]))
      r.fail(line, fmt::format("{} '{}': '{}' is not a number", "column", names[i], cells[i]));
  return values;
}

std::ifstream open(const Reader& r, const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) r.fail(0, "cannot open");
  return in;
}

}  // namespace

std::size_t PivFrame::valid_count() const {
  return static_cast<std::size_t>(std::count(valid.begin(), valid.end(), 1));
}

PivData read_piv_csv(const std::filesystem::path& path) {
  const Reader r{path.string()};
  std::ifstream in = open(r, path);
  PivData data;
  data.source = r.source;
  std::vector<std::string> names;
  std::array<int, num_columns> at{};
  std::map<double, std::size_t> frame_of_value;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto cells = split(t, ",");
    if (names.empty()) {
      names = cells;
      at = map_columns(r, line_no, names, true, data.frame_key);
      data.has_rms = at[col_urms] >= 0;
      continue;
    }
    if (cells.size() != names.size())
      r.fail(line_no, fmt::format("{} values, the header has {}", cells.size(), names.size()));
    const auto values = parse_values(r, line_no, cells, names);
    double key = NAN;
    if (at[col_frame] >= 0) {
      key = values[at[col_frame]];
      if (!std::isfinite(key))
        r.fail(line_no, fmt::format("{} must be a finite number", data.frame_key));
    }
    auto it = frame_of_value.find(std::isfinite(key) ? key : 0.0);
    if (it == frame_of_value.end()) {
      it = frame_of_value.emplace(std::isfinite(key) ? key : 0.0, data.frames.size()).first;
      PivFrame f;
      f.phase = key;
      f.label = data.frame_key.empty() ? "all" : fmt::format("{}={:.6g}", data.frame_key, key);
      data.frames.push_back(std::move(f));
    }
    add_point(r, line_no, at, values, data.frames[it->second]);
  }
  if (names.empty()) r.fail(0, "empty (no header line)");
  if (data.frames.empty()) r.fail(line_no, "no data rows after the header");
  return data;
}

PivData read_piv_tecplot(const std::filesystem::path& path) {
  const Reader r{path.string()};
  std::ifstream in = open(r, path);
  PivData data;
  data.source = r.source;
  std::vector<std::string> names;
  std::array<int, num_columns> at{};
  std::size_t expected = 0;
  int zone_line = 0;
  auto close_zone = [&](int line) {
    if (!data.frames.empty() && data.frames.back().size() != expected)
      r.fail(line,
             fmt::format("zone '{}' (line {}) declares I*J = {} points, found {}",
                         data.frames.back().label, zone_line, expected, data.frames.back().size()));
  };
  std::string line;
  int line_no = 0;
  bool in_zone_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string head = lower(t.substr(0, t.find_first_of(" =\t")));
    const bool alpha = std::isalpha(static_cast<unsigned char>(t[0])) && lower(t) != "nan" &&
                       lower(t.substr(0, 3)) != "nan";
    if (head == "title") continue;
    if (head == "variables") {
      if (!names.empty()) r.fail(line_no, "a second VARIABLES line");
      const auto eq = t.find('=');
      if (eq == std::string::npos) r.fail(line_no, "VARIABLES without '='");
      for (auto& n : split(t.substr(eq + 1), ", \t"))
        if (!n.empty()) names.push_back(n);
      at = map_columns(r, line_no, names, false, data.frame_key);
      data.has_rms = at[col_urms] >= 0;
      continue;
    }
    if (head == "zone" || (in_zone_header && alpha && t.find('=') != std::string::npos)) {
      if (names.empty()) r.fail(line_no, "ZONE before the VARIABLES line");
      if (head == "zone") {
        if (in_zone_header)  // the previous zone ended before its first data line
          r.fail(zone_line, fmt::format("zone '{}' has no data (the next ZONE is on line {})",
                                        data.frames.back().label, line_no));
        close_zone(line_no);
        zone_line = line_no;
        data.frames.emplace_back();
        data.frames.back().label = fmt::format("zone {}", data.frames.size());
      }
      in_zone_header = true;
      PivFrame& f = data.frames.back();
      const std::string body = head == "zone" ? t.substr(4) : t;
      for (const auto& item : split(body, ", \t")) {
        if (item.empty()) continue;
        const auto eq = item.find('=');
        if (eq == std::string::npos) r.fail(line_no, fmt::format("'{}' is not KEY=VALUE", item));
        const std::string key = lower(trim(item.substr(0, eq))), value = trim(item.substr(eq + 1));
        double number = 0;
        const bool numeric = parse_number(value, number) && !value.empty();
        if (key == "t") {
          f.label = value;
        } else if (key == "i" || key == "j" || key == "k") {
          if (!numeric || number < 1 || number != std::floor(number))
            r.fail(line_no, fmt::format("{} = '{}' must be a positive integer", key, value));
          if (key == "i") f.ni = int(number);
          if (key == "j") f.nj = int(number);
          if (key == "k" && number != 1) r.fail(line_no, "K > 1: PIV zones are planar");
        } else if (key == "solutiontime") {
          if (!numeric) r.fail(line_no, fmt::format("SOLUTIONTIME = '{}' is not a number", value));
          f.phase = number;
          data.frame_key = "time";
        } else if (key == "f" || key == "datapacking") {
          if (lower(value) != "point")
            r.fail(line_no, fmt::format("{}={} is not supported (only POINT)", key, value));
        } else if (key == "zonetype") {
          if (lower(value) != "ordered")
            r.fail(line_no, fmt::format("ZONETYPE={} is not supported (only ORDERED)", value));
        }  // STRANDID, C, DT and other display keys are ignored
      }
      continue;
    }
    // A data line.
    if (data.frames.empty()) r.fail(line_no, "data before the first ZONE line");
    PivFrame& f = data.frames.back();
    if (in_zone_header) {
      in_zone_header = false;
      if (f.ni == 0 || f.nj == 0)
        r.fail(zone_line, fmt::format("zone '{}' without {}", f.label, f.ni == 0 ? "I" : "J"));
      expected = std::size_t(f.ni) * std::size_t(f.nj);
    }
    std::vector<std::string> cells;
    for (auto& c : split(t, ", \t"))
      if (!c.empty()) cells.push_back(c);
    if (cells.size() != names.size())
      r.fail(line_no, fmt::format("{} values, VARIABLES names {}", cells.size(), names.size()));
    if (f.size() == expected)
      r.fail(line_no, fmt::format("zone '{}' (line {}) declares I*J = {} points, this is one more",
                                  f.label, zone_line, expected));
    add_point(r, line_no, at, parse_values(r, line_no, cells, names), f);
  }
  if (names.empty()) r.fail(0, line_no == 0 ? "empty" : "no VARIABLES line");
  if (data.frames.empty()) r.fail(line_no, "no ZONE");
  if (in_zone_header)
    r.fail(zone_line, fmt::format("zone '{}' has no data", data.frames.back().label));
  close_zone(line_no);
  return data;
}

void scale_piv(PivData& data, const PivUnits& units) {
  for (double f : {units.length, units.velocity})
    if (!(f > 0) || !std::isfinite(f))
      throw std::invalid_argument(
          fmt::format("PIV file '{}': length scale {} and velocity scale {} must be positive",
                      data.source, units.length, units.velocity));
  for (PivFrame& f : data.frames) {
    for (auto* v : {&f.x, &f.y})
      for (double& a : *v) a *= units.length;
    for (auto* v : {&f.u, &f.v, &f.u_rms, &f.v_rms})
      for (double& a : *v) a *= units.velocity;
  }
}

PivData read_piv(const std::filesystem::path& path, const PivUnits& units) {
  const std::string ext = lower(path.extension().string());
  PivData data;
  if (ext == ".csv") {
    data = read_piv_csv(path);
  } else if (ext == ".dat" || ext == ".tec" || ext == ".plt" || ext == ".txt") {
    data = read_piv_tecplot(path);
  } else {
    throw std::runtime_error(fmt::format(
        "PIV file '{}': extension '{}' is neither .csv nor Tecplot ASCII (.dat, .tec, .plt, .txt)",
        path.string(), ext));
  }
  scale_piv(data, units);
  return data;
}

}  // namespace valsalva::io
