// Case options (`valsalva validate CASE --set key=value`); see case.hpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "validation/case.hpp"

namespace valsalva::validation {

namespace {

// The number in all of `text`, or NaN.
double whole_number(const std::string& text) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nan("");
  }
  return used == text.size() ? x : std::nan("");
}

bool accepts(const CaseOption& o, const std::string& value) {
  if (o.kind == CaseOption::Kind::directory) return std::filesystem::is_directory(value);
  if (o.kind == CaseOption::Kind::choice)
    return std::find(o.choices.begin(), o.choices.end(), value) != o.choices.end();
  const double x = whole_number(value);
  if (!(x >= o.lo && x <= o.hi)) return false;
  return o.kind == CaseOption::Kind::real || x == std::floor(x);
}

}  // namespace

CaseOption CaseOption::real(std::string key, std::string help, double lo, double hi) {
  return {std::move(key), std::move(help), Kind::real, lo, hi, {}};
}

CaseOption CaseOption::integer(std::string key, std::string help, int lo, int hi) {
  return {std::move(key), std::move(help), Kind::integer, double(lo), double(hi), {}};
}

CaseOption CaseOption::choice(std::string key, std::string help, std::vector<std::string> words) {
  return {std::move(key), std::move(help), Kind::choice, 0, 0, std::move(words)};
}

CaseOption CaseOption::directory(std::string key, std::string help) {
  return {std::move(key), std::move(help), Kind::directory, 0, 0, {}};
}

std::string CaseOption::accepted() const {
  if (kind == Kind::directory) return "an existing folder";
  if (kind == Kind::real) return fmt::format("a number in [{}, {}]", lo, hi);
  if (kind == Kind::integer) return fmt::format("an integer in [{}, {}]", lo, hi);
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  return "one of " + list;
}

std::string Context::option(const std::string& key, const std::string& fallback) const {
  const auto it = options.find(key);
  return it == options.end() ? fallback : it->second;
}

double Context::option_real(const std::string& key, double fallback) const {
  const auto it = options.find(key);
  return it == options.end() ? fallback : std::stod(it->second);
}

int Context::option_int(const std::string& key, int fallback) const {
  const auto it = options.find(key);
  return it == options.end() ? fallback : std::stoi(it->second);
}

std::map<std::string, std::string> parse_case_options(const Case& case_def,
                                                      const std::vector<std::string>& settings) {
  std::map<std::string, std::string> options;
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument(
          fmt::format("validate: --set '{}' is not of the form key=value", s));
    const std::string key = s.substr(0, eq), value = s.substr(eq + 1);
    const auto option = std::find_if(case_def.options.begin(), case_def.options.end(),
                                     [&](const CaseOption& o) { return o.key == key; });
    if (option == case_def.options.end()) {
      std::string keys;
      for (const auto& o : case_def.options) keys += (keys.empty() ? "" : ", ") + o.key;
      throw std::invalid_argument(
          fmt::format("validate: case '{}' has no option '{}' (its options: {})", case_def.name,
                      key, keys.empty() ? "none" : keys));
    }
    if (!accepts(*option, value))
      throw std::invalid_argument(fmt::format("validate: --set {}={} is not accepted (expected {})",
                                              key, value, option->accepted()));
    if (!options.emplace(key, value).second)
      throw std::invalid_argument(fmt::format("validate: option '{}' is set twice", key));
  }
  return options;
}

}  // namespace valsalva::validation
