#include "scene/scene_schema.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

#include "scene/scene_keys.hpp"

namespace valsalva::scene {

const Schema& scene_schema() {
  static const Schema schema = [] {
    Schema s;
    declare_run_keys(s);
    declare_mesh_keys(s);
    declare_partition_keys(s);
    declare_flow_keys(s);
    declare_rheology_keys(s);
    declare_forcing_keys(s);
    declare_boundary_keys(s);
    declare_les_keys(s);
    declare_analysis_keys(s);
    declare_section_keys(s);
    declare_structure_keys(s);
    declare_valve_keys(s);
    s.check();
    return s;
  }();
  return schema;
}

// ---- KeyDecl setters ---------------------------------------------------------------------------

KeyDecl& KeyDecl::def(bool v) {
  return fallback = v, *this;
}
KeyDecl& KeyDecl::def(int v) {
  return fallback = std::int64_t{v}, *this;
}
KeyDecl& KeyDecl::def(std::int64_t v) {
  return fallback = v, *this;
}
KeyDecl& KeyDecl::def(double v) {
  return fallback = v, *this;
}
KeyDecl& KeyDecl::def(const char* v) {
  return fallback = std::string(v), *this;
}
KeyDecl& KeyDecl::def(std::string v) {
  return fallback = std::move(v), *this;
}
KeyDecl& KeyDecl::def(std::array<double, 3> v) {
  return fallback = v, *this;
}
KeyDecl& KeyDecl::def(std::array<int, 3> v) {
  fallback = std::array<std::int64_t, 3>{v[0], v[1], v[2]};
  return *this;
}
KeyDecl& KeyDecl::def(std::vector<std::string> v) {
  return fallback = std::move(v), *this;
}
KeyDecl& KeyDecl::def(std::vector<double> v) {
  return fallback = std::move(v), *this;
}
KeyDecl& KeyDecl::def(std::map<std::string, double> v) {
  return fallback = std::move(v), *this;
}
KeyDecl& KeyDecl::required() {
  return is_required = true, *this;
}
KeyDecl& KeyDecl::note(std::string v) {
  return default_note = std::move(v), *this;
}
KeyDecl& KeyDecl::unit_of(std::string v) {
  return unit = std::move(v), *this;
}
KeyDecl& KeyDecl::doc(std::string v) {
  return text = std::move(v), *this;
}
KeyDecl& KeyDecl::values(std::vector<std::string> v) {
  return choices = std::move(v), *this;
}
KeyDecl& KeyDecl::at_least(double v) {
  return lower = Bound{v, true}, *this;
}
KeyDecl& KeyDecl::above(double v) {
  return lower = Bound{v, false}, *this;
}
KeyDecl& KeyDecl::at_most(double v) {
  return upper = Bound{v, true}, *this;
}
KeyDecl& KeyDecl::below(double v) {
  return upper = Bound{v, false}, *this;
}
KeyDecl& KeyDecl::one_of(std::vector<std::int64_t> v) {
  return integers = std::move(v), *this;
}
KeyDecl& KeyDecl::in_range(double lo, double hi) {
  lower = Bound{lo, true};
  upper = Bound{hi, true};
  return *this;
}
KeyDecl& KeyDecl::at_least_size(std::size_t n) {
  return min_size = n, *this;
}

// ---- paths --------------------------------------------------------------------------------------

std::vector<std::string> split_path(std::string_view path) {
  std::vector<std::string> out;
  std::size_t start = 0;
  // Wildcard labels may not contain dots, so a plain split is enough.
  while (true) {
    const auto dot = path.find('.', start);
    out.emplace_back(path.substr(start, dot - start));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return out;
}

bool is_wildcard(std::string_view segment) {
  return segment == "*" || (segment.size() > 2 && segment.front() == '<' && segment.back() == '>');
}

std::string normalise_pattern(std::string_view path) {
  std::string out;
  for (const auto& segment : split_path(path)) {
    if (!out.empty()) out += '.';
    out += is_wildcard(segment) ? std::string("*") : segment;
  }
  return out;
}

bool pattern_matches(std::string_view pattern, std::string_view concrete) {
  const auto p = split_path(pattern);
  const auto c = split_path(concrete);
  if (p.size() != c.size()) return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] != "*" && p[i] != c[i]) return false;
  return true;
}

static bool is_prefix_of(std::string_view prefix, std::string_view path) {
  return path == prefix ||
         (path.size() > prefix.size() && path.starts_with(prefix) && path[prefix.size()] == '.');
}

static std::string parent_of(std::string_view path) {
  const auto dot = path.rfind('.');
  return dot == std::string_view::npos ? std::string() : std::string(path.substr(0, dot));
}

// ---- Schema -------------------------------------------------------------------------------------

void Schema::section(std::string path, std::string doc) {
  auto pattern = normalise_pattern(path);
  sections_.push_back({std::move(path), std::move(pattern), std::move(doc)});
}

KeyDecl& Schema::add(std::string path, KeyType type) {
  KeyDecl key;
  key.pattern = normalise_pattern(path);
  key.path = std::move(path);
  key.type = type;
  keys_.push_back(std::move(key));
  return keys_.back();
}

KeyDecl& Schema::boolean(std::string path) {
  return add(std::move(path), KeyType::boolean);
}
KeyDecl& Schema::integer(std::string path) {
  return add(std::move(path), KeyType::integer);
}
KeyDecl& Schema::real(std::string path) {
  return add(std::move(path), KeyType::real);
}
KeyDecl& Schema::string(std::string path) {
  return add(std::move(path), KeyType::string);
}
KeyDecl& Schema::choice(std::string path, std::vector<std::string> values) {
  return add(std::move(path), KeyType::choice).values(std::move(values));
}
KeyDecl& Schema::real3(std::string path) {
  return add(std::move(path), KeyType::real3);
}
KeyDecl& Schema::int3(std::string path) {
  return add(std::move(path), KeyType::int3);
}
KeyDecl& Schema::string_list(std::string path) {
  return add(std::move(path), KeyType::string_list);
}
KeyDecl& Schema::real_list(std::string path) {
  return add(std::move(path), KeyType::real_list);
}
KeyDecl& Schema::real_table(std::string path) {
  return add(std::move(path), KeyType::real_table);
}

void Schema::when(std::string prefix, std::string key, std::vector<std::string> values) {
  auto pattern = normalise_pattern(key);
  conditions_.push_back(
      {normalise_pattern(prefix), std::move(pattern), std::move(key), std::move(values)});
}

const KeyDecl* Schema::find(std::string_view concrete) const {
  // A literal segment wins over a wildcard at the same place (fewest wildcards first).
  const KeyDecl* best = nullptr;
  long best_wild = -1;
  for (const auto& key : keys_) {
    if (!pattern_matches(key.pattern, concrete)) continue;
    const long wild = std::count(key.pattern.begin(), key.pattern.end(), '*');
    if (!best || wild < best_wild) best = &key, best_wild = wild;
  }
  return best;
}

const SectionDecl* Schema::find_section(std::string_view concrete) const {
  for (const auto& s : sections_)
    if (pattern_matches(s.pattern, concrete)) return &s;
  return nullptr;
}

bool Schema::is_key(std::string_view pattern) const {
  return std::any_of(keys_.begin(), keys_.end(),
                     [&](const KeyDecl& k) { return k.pattern == pattern; });
}

bool Schema::is_table(std::string_view pattern) const {
  return std::any_of(keys_.begin(), keys_.end(), [&](const KeyDecl& k) {
    return k.pattern != pattern && is_prefix_of(pattern, k.pattern);
  });
}

std::vector<std::string> Schema::children(std::string_view table_pattern) const {
  std::vector<std::string> out;
  const std::size_t depth = table_pattern.empty() ? 0 : split_path(table_pattern).size();
  for (const auto& key : keys_) {
    if (!table_pattern.empty() && !is_prefix_of(table_pattern, key.pattern)) continue;
    if (key.pattern == table_pattern) continue;
    auto name = split_path(key.path)[depth];
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}

std::vector<const Condition*> Schema::conditions_for(std::string_view pattern) const {
  std::vector<const Condition*> out;
  for (const auto& c : conditions_)
    if (is_prefix_of(c.prefix, pattern)) out.push_back(&c);
  return out;
}

// ---- declaration checks -------------------------------------------------------------------------

static bool value_has_type(const KeyValue& v, KeyType type) {
  switch (type) {
    case KeyType::boolean:
      return std::holds_alternative<bool>(v);
    case KeyType::integer:
      return std::holds_alternative<std::int64_t>(v);
    case KeyType::real:
      return std::holds_alternative<double>(v);
    case KeyType::string:
    case KeyType::choice:
      return std::holds_alternative<std::string>(v);
    case KeyType::real3:
      return std::holds_alternative<std::array<double, 3>>(v);
    case KeyType::int3:
      return std::holds_alternative<std::array<std::int64_t, 3>>(v);
    case KeyType::string_list:
      return std::holds_alternative<std::vector<std::string>>(v);
    case KeyType::real_list:
      return std::holds_alternative<std::vector<double>>(v);
    case KeyType::real_table:
      return std::holds_alternative<std::map<std::string, double>>(v);
  }
  return false;
}

bool within_bounds(const KeyDecl& key, double x) {
  if (key.lower && (key.lower->inclusive ? x < key.lower->value : x <= key.lower->value))
    return false;
  if (key.upper && (key.upper->inclusive ? x > key.upper->value : x >= key.upper->value))
    return false;
  return key.integers.empty() ||
         std::find(key.integers.begin(), key.integers.end(), x) != key.integers.end();
}

static bool default_is_accepted(const KeyDecl& key) {
  const KeyValue& v = *key.fallback;
  auto ok_all = [&](const auto& range) {
    return std::all_of(range.begin(), range.end(),
                       [&](auto x) { return within_bounds(key, double(x)); });
  };
  auto chosen = [&](const std::string& s) {
    return key.choices.empty() ||
           std::find(key.choices.begin(), key.choices.end(), s) != key.choices.end();
  };
  switch (key.type) {
    case KeyType::integer:
      return within_bounds(key, double(std::get<std::int64_t>(v)));
    case KeyType::real:
      return within_bounds(key, std::get<double>(v));
    case KeyType::real3:
      return ok_all(std::get<std::array<double, 3>>(v));
    case KeyType::int3:
      return ok_all(std::get<std::array<std::int64_t, 3>>(v));
    case KeyType::real_list: {
      const auto& list = std::get<std::vector<double>>(v);
      return list.size() >= key.min_size && ok_all(list);
    }
    case KeyType::real_table:
      return std::all_of(std::get<std::map<std::string, double>>(v).begin(),
                         std::get<std::map<std::string, double>>(v).end(),
                         [&](const auto& kv) { return within_bounds(key, kv.second); });
    case KeyType::choice:
      return chosen(std::get<std::string>(v));
    case KeyType::string_list: {
      const auto& list = std::get<std::vector<std::string>>(v);
      return list.size() >= key.min_size && std::all_of(list.begin(), list.end(), chosen);
    }
    default:
      return true;
  }
}

void Schema::check() const {
  auto fail = [](const std::string& path, const std::string& what) {
    throw std::logic_error(fmt::format("scene schema: key '{}': {}", path, what));
  };
  std::set<std::string> seen;
  for (const auto& key : keys_) {
    if (!seen.insert(key.pattern).second) fail(key.path, "declared twice");
    if (is_table(key.pattern)) fail(key.path, "is both a key and a table");
    if (key.is_required == key.fallback.has_value())
      fail(key.path, "needs exactly one of a default or required()");
    if (key.text.empty()) fail(key.path, "has no doc line");
    if (key.unit.empty()) fail(key.path, "has no unit (use \"-\" for none)");
    if (key.type == KeyType::choice && key.choices.empty()) fail(key.path, "choice without values");
    if (!key.integers.empty() && key.type != KeyType::integer)
      fail(key.path, "one_of() is for integer keys");
    if (key.fallback && !value_has_type(*key.fallback, key.type))
      fail(key.path, "default has the wrong type");
    if (key.fallback && !default_is_accepted(key))
      fail(key.path, fmt::format("default {} is outside its accepted values {}",
                                 format_value(*key.fallback), accepted_values(key)));
    if (!find_section(parent_of(key.pattern)) && key.pattern.find('.') != std::string::npos)
      fail(key.path, "its section '" + parent_of(key.path) + "' is not declared with section()");
  }
  for (const auto& c : conditions_) {
    const auto* key = find(c.key);
    if (!key || (key->type != KeyType::choice && key->type != KeyType::string))
      fail(c.key, "a condition needs a declared string or choice key");
    if (!is_key(c.prefix) && !is_table(c.prefix)) fail(c.prefix, "condition on an undeclared path");
    // Defaults are filled in declaration order, so the condition key must come first.
    const auto pos = [&](std::string_view p) {
      for (std::size_t i = 0; i < keys_.size(); ++i)
        if (is_prefix_of(p, keys_[i].pattern)) return i;
      return keys_.size();
    };
    if (pos(c.key) > pos(c.prefix)) fail(c.prefix, "declared before its condition key " + c.key);
  }
}

// ---- text helpers -------------------------------------------------------------------------------

std::string type_name(KeyType type) {
  switch (type) {
    case KeyType::boolean:
      return "bool";
    case KeyType::integer:
      return "int";
    case KeyType::real:
      return "float";
    case KeyType::string:
      return "string";
    case KeyType::choice:
      return "enum";
    case KeyType::real3:
      return "float[3]";
    case KeyType::int3:
      return "int[3]";
    case KeyType::string_list:
      return "string[]";
    case KeyType::real_list:
      return "float[]";
    case KeyType::real_table:
      return "table of floats";
  }
  return "?";
}

static std::string number(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

static std::string toml_float(double x) {
  auto s = number(x);
  if (std::isfinite(x) && s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

static std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

static std::string quoted_list(const std::vector<std::string>& list) {
  std::string out;
  for (const auto& s : list) out += (out.empty() ? "" : ", ") + quoted(s);
  return out;
}

std::string accepted_values(const KeyDecl& key) {
  std::string range;
  if (key.lower && key.upper)
    range = fmt::format("{}{}, {}{}", key.lower->inclusive ? '[' : '(', number(key.lower->value),
                        number(key.upper->value), key.upper->inclusive ? ']' : ')');
  else if (key.lower)
    range = fmt::format("{} {}", key.lower->inclusive ? ">=" : ">", number(key.lower->value));
  else if (key.upper)
    range = fmt::format("{} {}", key.upper->inclusive ? "<=" : "<", number(key.upper->value));
  const std::string size = key.min_size ? fmt::format("at least {} values", key.min_size) : "";
  auto join = [](std::string a, const std::string& b) {
    return a.empty() ? b : b.empty() ? a : a + ", " + b;
  };
  switch (key.type) {
    case KeyType::boolean:
      return "true, false";
    case KeyType::string:
      return "any string";
    case KeyType::choice:
      return quoted_list(key.choices);
    case KeyType::string_list:
      return join(size, key.choices.empty()
                            ? "any strings"
                            : "each of " + quoted_list(key.choices) + ", no repeats");
    case KeyType::integer:
      if (!key.integers.empty()) return fmt::format("one of {}", fmt::join(key.integers, ", "));
      return range.empty() ? "any" : range;
    case KeyType::real:
      return range.empty() ? "any" : range;
    case KeyType::real3:
    case KeyType::int3:
      return range.empty() ? "3 values" : "3 values, each " + range;
    case KeyType::real_table:
      return range.empty() ? "any" : "each " + range;
    case KeyType::real_list:
      return join(size, range.empty() ? "any" : "each " + range);
  }
  return "";
}

std::string format_value(const KeyValue& value) {
  struct Visitor {
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const { return toml_float(v); }
    std::string operator()(const std::string& v) const { return quoted(v); }
    std::string operator()(const std::array<double, 3>& v) const {
      return fmt::format("[{}, {}, {}]", toml_float(v[0]), toml_float(v[1]), toml_float(v[2]));
    }
    std::string operator()(const std::array<std::int64_t, 3>& v) const {
      return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]);
    }
    std::string operator()(const std::vector<std::string>& v) const {
      return "[" + quoted_list(v) + "]";
    }
    std::string operator()(const std::vector<double>& v) const {
      std::string out;
      for (double x : v) out += (out.empty() ? "" : ", ") + toml_float(x);
      return "[" + out + "]";
    }
    std::string operator()(const std::map<std::string, double>& v) const {
      std::string out;
      for (const auto& [k, x] : v) {
        const bool bare = !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
        });
        out += (out.empty() ? "" : ", ") + (bare ? k : quoted(k)) + " = " + toml_float(x);
      }
      return "{ " + out + (out.empty() ? "}" : " }");
    }
  };
  return std::visit(Visitor{}, value);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Levenshtein distance, one row at a time.
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace valsalva::scene
