#include "validation/docs_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace valsalva::validation {

using json = nlohmann::ordered_json;

std::string md_cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out;
}

void write_md_table(std::ostream& out, const std::vector<std::string>& columns,
                    const std::vector<std::vector<std::string>>& rows) {
  auto line = [&](const std::vector<std::string>& cells) {
    out << "|";
    for (std::size_t i = 0; i < columns.size(); ++i)
      out << " " << (i < cells.size() ? md_cell(cells[i]) : std::string()) << " |";
    out << "\n";
  };
  line(columns);
  out << "|";
  for (std::size_t i = 0; i < columns.size(); ++i) out << "---|";
  out << "\n";
  for (const auto& row : rows) line(row);
}

std::string format_number(const json& value) {
  if (!value.is_number()) return "not finite";
  return fmt::format("{:.6g}", value.get<double>());
}

namespace {

double number_or_nan(const json& value) {
  return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// How far a metric's value is from failing, relative to its bound: > 0 passes, < 0 fails.
double room(const json& m) {
  const double v = number_or_nan(m.at("value"));
  const double r = number_or_nan(m.at("reference"));
  const double t = number_or_nan(m.at("tolerance"));
  if (!std::isfinite(v)) return -std::numeric_limits<double>::infinity();
  const auto check = m.at("check").get<std::string>();
  const double tiny = std::numeric_limits<double>::min();
  // An exact check (a flag, a count: no tolerance) has no margin to speak of: met or not.
  if (t == 0 && v == r) return 1.0;
  if (check == "within") return t == 0 ? -1.0 : (t - std::abs(v - r)) / std::abs(t);
  const double bound = check == "at_most" ? r + t : r - t;
  const double scale = std::max({std::abs(bound), std::abs(t), tiny});
  return (check == "at_most" ? bound - v : v - bound) / scale;
}

std::string date_of(const json& record) {
  return record.at("date").get<std::string>().substr(0, 10);
}

std::string short_commit(const std::string& commit) {
  const auto plus = commit.find('+');
  const auto hash = commit.substr(0, plus);
  return (hash.size() > 12 ? hash.substr(0, 12) : hash) +
         (plus == std::string::npos ? "" : " " + commit.substr(plus));
}

std::string level_title(const json& record) {
  return record.at("level").get<std::string>() == "quick" ? "Quick level" : "Full level";
}

}  // namespace

std::string metric_target(const json& m) {
  const auto check = m.at("check").get<std::string>();
  const double r = number_or_nan(m.at("reference"));
  const double t = number_or_nan(m.at("tolerance"));
  if (check == "within") return fmt::format("{:.6g} +- {:.6g}", r, t);
  if (check == "at_most") return fmt::format("<= {:.6g}", r + t);
  if (check == "at_least") return fmt::format(">= {:.6g}", r - t);
  return "check \"" + check + "\"";
}

std::vector<std::string> summary_cells(const json& record) {
  const auto date = date_of(record);
  if (record.at("origin") == "carried_over") {
    const auto& s = record.at("summary");
    return {s.at("metric").get<std::string>(), s.at("measured").get<std::string>(),
            s.at("target").get<std::string>(), s.at("result").get<std::string>(),
            date + " (carried over)"};
  }
  const auto& metrics = record.at("report").at("metrics");
  if (metrics.empty()) return {"no metrics", "-", "-", "FAIL (no metrics)", date};
  const json* shown = &metrics.front();
  std::size_t passing = 0;
  for (const auto& m : metrics) {
    if (m.at("pass").get<bool>()) ++passing;
    if (room(m) < room(*shown)) shown = &m;
  }
  const bool pass = record.at("report").at("pass").get<bool>();
  const auto result = pass ? fmt::format("pass ({} of {})", passing, metrics.size())
                           : fmt::format("FAIL ({} of {} pass)", passing, metrics.size());
  return {shown->at("name").get<std::string>(), format_number(shown->at("value")),
          metric_target(*shown), result, date};
}

void write_record_results(std::ostream& out, const json& record) {
  const auto command = record.at("command").get<std::string>();
  const auto commit = short_commit(record.at("commit").get<std::string>());
  if (record.at("origin") == "carried_over") {
    out << fmt::format(
        "**{}**, carried over (not re-run since it was written down): {}; `{}`, measured {}, "
        "machine: {}. {}.\n\n",
        level_title(record), record.at("source").get<std::string>(), command,
        record.at("date").get<std::string>(), record.at("machine").get<std::string>(),
        record.at("pass").get<bool>() ? "Met when measured" : "Not met when measured");
    for (const auto& table : record.at("tables")) {
      if (table.contains("title")) out << table.at("title").get<std::string>() << "\n\n";
      std::vector<std::vector<std::string>> rows;
      for (const auto& row : table.at("rows")) rows.push_back(row.get<std::vector<std::string>>());
      write_md_table(out, table.at("columns").get<std::vector<std::string>>(), rows);
      out << "\n";
    }
    return;
  }
  const auto& report = record.at("report");
  const auto& metrics = report.at("metrics");
  std::size_t passing = 0;
  std::vector<std::vector<std::string>> rows;
  for (const auto& m : metrics) {
    const bool pass = m.at("pass").get<bool>();
    if (pass) ++passing;
    rows.push_back({m.at("name").get<std::string>(), format_number(m.at("value")), metric_target(m),
                    pass ? "pass" : "FAIL"});
  }
  out << fmt::format(
      "**{}**, measured {} by `{}` at commit {} ({}; {} rank{}, {:.0f} s wall): {}, {} of {} "
      "metrics pass.\n\n",
      level_title(record), record.at("date").get<std::string>(), command, commit,
      record.at("machine").get<std::string>(), report.at("ranks").get<int>(),
      report.at("ranks").get<int>() == 1 ? "" : "s",
      report.at("wall_seconds").is_number() ? report.at("wall_seconds").get<double>() : 0.0,
      report.at("pass").get<bool>() ? "PASS" : "FAIL", passing, metrics.size());
  write_md_table(out, {"metric", "measured", "target", "result"}, rows);
  out << "\n";
}

}  // namespace valsalva::validation
