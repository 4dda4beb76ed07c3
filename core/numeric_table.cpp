#include "core/numeric_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>

namespace valsalva::core {

namespace {

bool is_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '(' ||
           c == ')' || c == '/' || c == '^' || c == '-' || c == ' ';
  });
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// from_chars accepts "nan" and "inf" and reports overflow as out of range: all refused.
bool parse(const std::string& s, double& x) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(x);
}

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

}  // namespace

std::vector<double> NumericTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end())
    throw TableError(
        fmt::format("'{}': no column '{}' (columns: {})", source, name, fmt::join(columns, ", ")));
  const auto c = static_cast<std::size_t>(it - columns.begin());
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(r[c]);
  return out;
}

TableLines::TableLines(const std::filesystem::path& file, TableFormat format)
    : in_(file), format_(std::move(format)), source_(file.string()) {
  if (!in_) throw TableError(fmt::format("'{}': cannot open", source_));
}

bool TableLines::next() {
  while (std::getline(in_, text_)) {
    ++line_;
    const auto start = text_.find_first_not_of(" \t\r");
    if (start != std::string::npos && text_[start] != '#') return true;
  }
  return false;
}

// Comma-separated fields with the surrounding blanks trimmed, or (blank_separated) runs of
// characters other than ',', ';' and blanks; a separator inside double quotes (quoted) does not
// separate, and the quotes are dropped.
std::vector<TableField> TableLines::fields(std::size_t from) const {
  const std::string& line = text_;
  const bool blanks = format_.blank_separated;
  auto separates = [&](char c) { return c == ',' || (blanks && (c == ';' || is_blank(c))); };
  std::vector<TableField> out;
  std::size_t i = std::min(from, line.size());
  while (true) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    std::string text;
    bool in_quotes = false;
    for (; i < line.size() && (in_quotes || !separates(line[i])); ++i) {
      if (format_.quoted && line[i] == '"')
        in_quotes = !in_quotes;
      else
        text += line[i];
    }
    while (!text.empty() && is_blank(text.back())) text.pop_back();
    if (!(blanks && text.empty() && start == i)) out.push_back({text, static_cast<int>(start) + 1});
    if (i >= line.size()) break;
    ++i;  // the separator
    if (blanks)
      while (i < line.size() && separates(line[i])) ++i;
  }
  return out;
}

TableError TableLines::error(int column, const std::string& what) const {
  return TableError(fmt::format("{}:{}:{}: {}", source_, line_, column, what));
}

bool TableLines::all_names(const std::vector<TableField>& fields) {
  return !fields.empty() && std::all_of(fields.begin(), fields.end(),
                                        [](const TableField& f) { return is_name(f.text); });
}

std::vector<std::string> TableLines::header(const std::vector<TableField>& fields) const {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const auto& f = fields[i];
    if (!is_name(f.text))
      throw error(f.column, fmt::format("'{}' in the header line: a header holds column names "
                                        "only (a first data row with a typo is not a header)",
                                        f.text));
    for (std::size_t j = 0; j < i; ++j)
      if (lower(fields[j].text) == lower(f.text))
        throw error(f.column, fmt::format("column '{}' appears twice (columns {} and {})", f.text,
                                          j + 1, i + 1));
    names.push_back(f.text);
  }
  return names;
}

double TableLines::number(const TableField& field, const std::string& name, bool maskable) const {
  double x = 0;
  if (parse(field.text, x)) return x;
  if (maskable && (field.text.empty() || lower(field.text) == "nan")) return NAN;
  throw error(field.column, fmt::format("'{}'{} is not a finite number{}", field.text,
                                        name.empty() ? "" : " (column '" + name + "')",
                                        maskable ? " (nor empty or nan, a masked value)" : ""));
}

std::vector<double> TableLines::values(const std::vector<TableField>& fields,
                                       const std::vector<std::string>& names,
                                       std::size_t width) const {
  if (fields.empty()) throw error(1, "separators only, no values");
  if (width > 0 && fields.size() != width)
    throw error(1, fmt::format("{} values, expected {}{}", fields.size(), width,
                               names.empty() ? "" : " (the header's columns)"));
  std::vector<double> row(fields.size());
  for (std::size_t c = 0; c < fields.size(); ++c) {
    const std::string name = c < names.size() ? names[c] : "";
    row[c] = number(fields[c], name, !name.empty() && format_.maskable && format_.maskable(name));
  }
  return row;
}

NumericTable read_numeric_table(const std::filesystem::path& file, const TableFormat& format) {
  TableLines lines(file, format);
  NumericTable t;
  t.source = lines.source();
  std::size_t width = format.width;
  bool first = true;
  while (lines.next()) {
    const auto fields = lines.fields();
    if (first) {
      first = false;
      const bool some_name = std::any_of(fields.begin(), fields.end(), [](const TableField& f) {
        return TableLines::all_names({f});
      });
      if (some_name && format.header != TableHeader::none) {
        t.columns = lines.header(fields);
        if (width > 0 && fields.size() != width)
          throw lines.error(1, fmt::format("{} columns, expected {}", fields.size(), width));
        width = fields.size();
        continue;
      }
      if (format.header == TableHeader::required)
        throw lines.error(1, "expected a header line of column names");
    }
    if (width == 0) width = fields.size();
    t.rows.push_back(lines.values(fields, t.columns, width));
    t.lines.push_back(lines.line());
  }
  return t;
}

NumericTable read_numeric_table(const std::filesystem::path& file, TableHeader header,
                                std::size_t width, bool blank_separated) {
  TableFormat format;
  format.header = header;
  format.width = width;
  format.blank_separated = blank_separated;
  return read_numeric_table(file, format);
}

}  // namespace valsalva::core
