#include "analysis/piv_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/numeric_table.hpp"

namespace valsalva::analysis {

namespace {

enum Column { col_x, col_y, col_u, col_v, col_urms, col_vrms, col_valid, col_frame, num_columns };
const char* const column_names[] = {"x", "y", "u", "v", "u_rms", "v_rms", "valid"};
const char* const known_list = "x, y, u, v, u_rms, v_rms, valid";

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Column index of a name, or -1 (frame keys handled by the caller).
int known_column(const std::string& name) {
  for (int c = 0; c < 7; ++c)
    if (name == column_names[c]) return c;
  return -1;
}

// The velocity columns, where an empty field or nan is a masked vector (core/numeric_table.hpp).
core::TableFormat piv_format(bool blank_separated) {
  core::TableFormat f;
  f.header = core::TableHeader::required;
  f.blank_separated = blank_separated;
  f.quoted = true;
  f.maskable = [](const std::string& name) {
    const int c = known_column(lower(name));
    return c == col_u || c == col_v || c == col_urms || c == col_vrms;
  };
  return f;
}

// Maps header names (checked by TableLines::header) to columns; errors for unknown or missing
// names at their position on the line.
std::array<int, num_columns> map_columns(const core::TableLines& lines,
                                         const std::vector<core::TableField>& fields,
                                         bool allow_frame, std::string& frame_key) {
  std::array<int, num_columns> at;
  at.fill(-1);
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string n = lower(fields[i].text);
    int c = known_column(n);
    if (c < 0 && allow_frame && (n == "phase" || n == "time")) {
      if (at[col_frame] >= 0)
        throw lines.error(fields[i].column, "both 'phase' and 'time' columns");
      c = col_frame;
      frame_key = n;
    }
    if (c < 0)
      throw lines.error(
          fields[i].column,
          fmt::format("unknown {} '{}' (known: {}{})", allow_frame ? "column" : "variable",
                      fields[i].text, known_list, allow_frame ? ", phase, time" : ""));
    at[c] = static_cast<int>(i);
  }
  for (int c : {col_x, col_y, col_u, col_v})
    if (at[c] < 0) throw lines.error(1, fmt::format("missing column '{}'", column_names[c]));
  if ((at[col_urms] >= 0) != (at[col_vrms] >= 0))
    throw lines.error(1, "u_rms and v_rms come together");
  return at;
}

// Appends one point; `values` indexed by the file's columns (x, y, valid, phase finite: the
// table reader refuses anything else outside the maskable velocity columns).
void add_point(const core::TableLines& lines, const std::vector<core::TableField>& fields,
               const std::array<int, num_columns>& at, const std::vector<double>& values,
               PivFrame& f) {
  auto get = [&](int c) { return at[c] >= 0 ? values[at[c]] : NAN; };
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
    if (flag != 0 && flag != 1)
      throw lines.error(fields[at[col_valid]].column,
                        fmt::format("valid = {} must be 0 or 1", flag));
    ok = ok && flag == 1;
  }
  f.valid.push_back(ok ? 1 : 0);
}

}  // namespace

std::size_t PivFrame::valid_count() const {
  return static_cast<std::size_t>(std::count(valid.begin(), valid.end(), 1));
}

PivData read_piv_csv(const std::filesystem::path& path) {
  core::TableLines lines(path, piv_format(false));
  PivData data;
  data.source = lines.source();
  if (!lines.next())
    throw core::TableError(fmt::format("'{}': empty (no header line)", data.source));
  const auto header = lines.fields();
  const auto names = lines.header(header);
  const auto at = map_columns(lines, header, true, data.frame_key);
  data.has_rms = at[col_urms] >= 0;
  std::map<double, std::size_t> frame_of_value;
  while (lines.next()) {
    const auto fields = lines.fields();
    const auto values = lines.values(fields, names, names.size());
    const double key = at[col_frame] >= 0 ? values[at[col_frame]] : 0.0;
    auto it = frame_of_value.find(key);
    if (it == frame_of_value.end()) {
      it = frame_of_value.emplace(key, data.frames.size()).first;
      PivFrame f;
      f.phase = at[col_frame] >= 0 ? key : NAN;
      f.label = data.frame_key.empty() ? "all" : fmt::format("{}={:.6g}", data.frame_key, key);
      data.frames.push_back(std::move(f));
    }
    add_point(lines, fields, at, values, data.frames[it->second]);
  }
  if (data.frames.empty())
    throw lines.error(1, fmt::format("no data rows after the header (line {})", lines.line()));
  return data;
}

PivData read_piv_tecplot(const std::filesystem::path& path) {
  core::TableLines lines(path, piv_format(true));
  PivData data;
  data.source = lines.source();
  std::vector<std::string> names;
  std::array<int, num_columns> at{};
  std::size_t expected = 0;
  int zone_line = 0;
  auto zone_error = [&](const std::string& what) {
    return core::TableError(fmt::format("{}:{}:1: {}", data.source, zone_line, what));
  };
  // A zone must hold the I*J points it declares, whether a ZONE or the end of the file follows.
  auto close_zone = [&] {
    if (!data.frames.empty() && data.frames.back().size() != expected)
      throw zone_error(fmt::format("zone '{}' declares I*J = {} points, found {} (up to line {})",
                                   data.frames.back().label, expected, data.frames.back().size(),
                                   lines.line()));
  };
  bool in_zone_header = false, any_line = false;
  while (lines.next()) {
    any_line = true;
    const auto fields = lines.fields();
    if (fields.empty()) throw lines.error(1, "separators only, no values");
    const std::string& first = fields.front().text;
    const std::string head = lower(first.substr(0, first.find('=')));
    const bool key_value =
        std::isalpha(static_cast<unsigned char>(first[0])) && first.find('=') != std::string::npos;
    if (head == "title") continue;
    if (head == "variables") {
      if (!names.empty()) throw lines.error(1, "a second VARIABLES line");
      const auto eq = lines.text().find('=');
      if (eq == std::string::npos) throw lines.error(1, "VARIABLES without '='");
      const auto variables = lines.fields(eq + 1);
      names = lines.header(variables);
      at = map_columns(lines, variables, false, data.frame_key);
      data.has_rms = at[col_urms] >= 0;
      continue;
    }
    if (head == "zone" || (in_zone_header && key_value)) {
      if (names.empty()) throw lines.error(1, "ZONE before the VARIABLES line");
      if (head == "zone") {
        if (in_zone_header)  // the previous zone ended before its first data line
          throw zone_error(fmt::format("zone '{}' has no data (the next ZONE is on line {})",
                                       data.frames.back().label, lines.line()));
        close_zone();
        zone_line = lines.line();
        data.frames.emplace_back();
        data.frames.back().label = fmt::format("zone {}", data.frames.size());
      }
      in_zone_header = true;
      PivFrame& f = data.frames.back();
      for (std::size_t i = head == "zone" ? 1 : 0; i < fields.size(); ++i) {
        const auto& item = fields[i];
        const auto eq = item.text.find('=');
        if (eq == std::string::npos)
          throw lines.error(item.column, fmt::format("'{}' is not KEY=VALUE", item.text));
        const std::string key = lower(item.text.substr(0, eq));
        const core::TableField value{item.text.substr(eq + 1),
                                     item.column + static_cast<int>(eq) + 1};
        if (key == "t") {
          f.label = value.text;
        } else if (key == "i" || key == "j" || key == "k") {
          const double n = lines.number(value, key);
          if (n < 1 || n != std::floor(n) || n > 1e9)
            throw lines.error(value.column,
                              fmt::format("{} = {} must be a positive integer (<= 1e9)", key, n));
          if (key == "i") f.ni = static_cast<int>(n);
          if (key == "j") f.nj = static_cast<int>(n);
          if (key == "k" && n != 1) throw lines.error(value.column, "K > 1: PIV zones are planar");
        } else if (key == "solutiontime") {
          f.phase = lines.number(value, "SOLUTIONTIME");
          data.frame_key = "time";
        } else if (key == "f" || key == "datapacking") {
          if (lower(value.text) != "point")
            throw lines.error(value.column,
                              fmt::format("{}={} is not supported (only POINT)", key, value.text));
        } else if (key == "zonetype") {
          if (lower(value.text) != "ordered")
            throw lines.error(value.column, fmt::format("ZONETYPE={} is not supported (only "
                                                        "ORDERED)",
                                                        value.text));
        }  // STRANDID, C, DT and other display keys are ignored
      }
      continue;
    }
    // A data line.
    if (data.frames.empty()) throw lines.error(1, "data before the first ZONE line");
    PivFrame& f = data.frames.back();
    if (in_zone_header) {
      in_zone_header = false;
      if (f.ni == 0 || f.nj == 0)
        throw zone_error(fmt::format("zone '{}' without {}", f.label, f.ni == 0 ? "I" : "J"));
      expected = std::size_t(f.ni) * std::size_t(f.nj);
    }
    if (f.size() == expected)
      throw lines.error(1, fmt::format("zone '{}' (line {}) declares I*J = {} points, this is one "
                                       "more",
                                       f.label, zone_line, expected));
    add_point(lines, fields, at, lines.values(fields, names, names.size()), f);
  }
  if (names.empty())
    throw core::TableError(
        fmt::format("'{}': {}", data.source, any_line ? "no VARIABLES line" : "empty"));
  if (data.frames.empty()) throw lines.error(1, "no ZONE");
  if (in_zone_header)
    throw zone_error(fmt::format("zone '{}' has no data", data.frames.back().label));
  close_zone();
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

}  // namespace valsalva::analysis
