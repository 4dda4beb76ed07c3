#include "io/numeric_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>

namespace valsalva::io {

namespace {

struct Field {
  std::string text;
  int column = 1;  // from 1
};

// Comma-separated fields with the surrounding blanks (and a trailing '\r') trimmed; or, when
// `blank_separated`, runs of characters other than ',', ';' and blanks.
std::vector<Field> split(const std::string& line, bool blank_separated) {
  std::vector<Field> out;
  if (blank_separated) {
    const char* separators = ",; \t\r";
    for (std::size_t a = line.find_first_not_of(separators); a != std::string::npos;) {
      const std::size_t b = std::min(line.find_first_of(separators, a), line.size());
      out.push_back({line.substr(a, b - a), static_cast<int>(a) + 1});
      a = line.find_first_not_of(separators, b);
    }
    return out;
  }
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = std::min(line.find(',', begin), line.size());
    std::size_t a = begin, b = end;
    while (a < b && std::isspace(static_cast<unsigned char>(line[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(line[b - 1]))) --b;
    out.push_back({line.substr(a, b - a), static_cast<int>(a) + 1});
    if (end == line.size()) break;
    begin = end + 1;
  }
  return out;
}

bool is_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '(' ||
           c == ')' || c == '/' || c == '^' || c == '-' || c == ' ';
  });
}

// from_chars accepts "nan" and "inf" and reports overflow as out of range: all refused.
bool parse(const std::string& s, double& x) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(x);
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

NumericTable read_numeric_table(const std::filesystem::path& file, TableHeader header,
                                std::size_t width, bool blank_separated) {
  std::ifstream in(file);
  if (!in) throw TableError(fmt::format("'{}': cannot open", file.string()));
  NumericTable t;
  t.source = file.string();
  auto fail = [&](int line, int column, const std::string& what) {
    return TableError(fmt::format("{}:{}:{}: {}", t.source, line, column, what));
  };
  std::string line;
  bool first = true;
  for (int number = 1; std::getline(in, line); ++number) {
    const auto start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    const auto fields = split(line, blank_separated);
    if (first) {
      first = false;
      const auto names = std::count_if(fields.begin(), fields.end(),
                                       [](const Field& f) { return is_name(f.text); });
      if (names > 0 && header != TableHeader::none) {
        for (const auto& f : fields)
          if (!is_name(f.text))
            throw fail(number, f.column,
                       fmt::format("'{}' in the header line: a header holds column names only "
                                   "(a first data row with a typo is not a header)",
                                   f.text));
        for (std::size_t i = 0; i < fields.size(); ++i)
          for (std::size_t j = 0; j < i; ++j)
            if (fields[i].text == fields[j].text)
              throw fail(number, fields[i].column,
                         fmt::format("column '{}' appears twice (columns {} and {})",
                                     fields[i].text, j + 1, i + 1));
        for (const auto& f : fields) t.columns.push_back(f.text);
        if (width > 0 && fields.size() != width)
          throw fail(number, 1, fmt::format("{} columns, expected {}", fields.size(), width));
        width = fields.size();
        continue;
      }
      if (header == TableHeader::required)
        throw fail(number, 1, "expected a header line of column names");
    }
    if (width == 0) width = fields.size();
    if (fields.size() != width)
      throw fail(number, 1,
                 fmt::format("{} values, expected {}{}", fields.size(), width,
                             t.columns.empty() ? "" : " (the header's columns)"));
    std::vector<double> row(width);
    for (std::size_t c = 0; c < width; ++c)
      if (!parse(fields[c].text, row[c]))
        throw fail(number, fields[c].column,
                   fmt::format("'{}'{} is not a finite number", fields[c].text,
                               t.columns.empty() ? "" : " (column '" + t.columns[c] + "')"));
    t.rows.push_back(std::move(row));
    t.lines.push_back(number);
  }
  return t;
}

}  // namespace valsalva::io
