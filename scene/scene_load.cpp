// Scene loading: parse the TOML, walk it against the schema (unknown keys, types, ranges,
// accepted values), fill defaults, check required and conditional keys, and report every
// problem at once with FILE:LINE:COLUMN.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "scene/scene.hpp"

namespace valsalva::scene {
namespace {

std::string join(std::string_view a, std::string_view b) {
  return a.empty() ? std::string(b) : fmt::format("{}.{}", a, b);
}

std::string what_it_is(const toml::node& v) {
  switch (v.type()) {
    case toml::node_type::string:
      return fmt::format("the string \"{}\"", *v.value<std::string>());
    case toml::node_type::integer:
      return fmt::format("the integer {}", *v.value<std::int64_t>());
    case toml::node_type::floating_point:
      return fmt::format("the float {}", *v.value<double>());
    case toml::node_type::boolean:
      return *v.value<bool>() ? "true" : "false";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return fmt::format("an array of {}", v.as_array()->size());
    default:
      return "a date/time";
  }
}

std::string expected_phrase(KeyType type) {
  switch (type) {
    case KeyType::boolean:
      return "true or false";
    case KeyType::integer:
      return "an integer";
    case KeyType::real:
      return "a number";
    case KeyType::string:
    case KeyType::choice:
      return "a string";
    case KeyType::real3:
      return "an array of 3 numbers";
    case KeyType::int3:
      return "an array of 3 integers";
    case KeyType::string_list:
      return "an array of strings";
    case KeyType::real_list:
      return "an array of numbers";
    case KeyType::real_table:
      return "a table of numbers";
  }
  return "?";
}

// The closest candidate within a few edits (two, or one in three characters), or "".
std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    if (is_wildcard(c)) continue;
    const auto d = edit_distance(word, c);
    // Replacing every character is no hint ("ab" -> "dt").
    if (d < best_d && d < std::max(word.size(), c.size())) best = c, best_d = d;
  }
  return best;
}

class Loader {
 public:
  Loader(const Schema& schema, std::string file) : schema_(schema), file_(std::move(file)) {}

  void walk(const toml::table& in, const std::string& pattern, const std::string& concrete);
  void fill_defaults();
  void check_conditions();
  [[noreturn]] void fail();
  bool ok() const { return problems_.empty(); }

  toml::table out;
  std::map<std::string, Location> where;

 private:
  // Keys from --set overrides carry their own source name ("--set KEY=VALUE").
  Location at(const toml::source_region& r) const {
    return {r.path ? *r.path : file_, static_cast<int>(r.begin.line),
            static_cast<int>(r.begin.column)};
  }
  void problem(const Location& loc, std::string_view key, std::string_view text,
               std::string_view accepted = {}) {
    problems_.push_back({loc, format_problem(loc, key, text, accepted)});
  }
  void leaf(const KeyDecl& decl, const toml::node& v, const std::string& concrete);
  void unknown(const toml::node& v, const std::string& pattern, const std::string& concrete,
               const std::string& name);
  bool number(const KeyDecl& decl, const toml::node& v, const std::string& key, bool integer,
              std::string_view what, double& x);
  template <class Node>
  void insert(const std::string& concrete, Node&& node);
  toml::table& table_at(const std::vector<std::string>& segments, std::size_t count);
  std::vector<std::string> expand(const std::string& pattern) const;
  const Condition* failed_condition(const KeyDecl& decl, const std::string& concrete,
                                    std::string& actual, std::string* used = nullptr) const;
  Location nearest_location(std::string concrete) const;
  const toml::node* lookup(const std::string& concrete) const;

  struct Problem {
    Location loc;
    std::string text;
  };
  const Schema& schema_;
  std::string file_;
  std::vector<Problem> problems_;
  std::set<std::string> from_file_;
};

void Loader::walk(const toml::table& in, const std::string& pattern, const std::string& concrete) {
  for (auto&& [k, v] : in) {
    const std::string name(k.str());
    const std::string path = join(concrete, name);
    where[path] = at(k.source());
    std::string chosen = join(pattern, name);
    if (!schema_.is_key(chosen) && !schema_.is_table(chosen)) {
      chosen = join(pattern, "*");
      if (!schema_.is_key(chosen) && !schema_.is_table(chosen)) {
        unknown(v, pattern, concrete, name);
        continue;
      }
      if (name.empty() || name.find_first_of(". ") != std::string::npos) {
        problem(at(k.source()), path, "a table name must be non-empty, without dots or spaces");
        continue;
      }
    }
    if (schema_.is_key(chosen)) {
      leaf(*schema_.find(path), v, path);
    } else if (!v.is_table()) {
      problem(at(v.source()), path, "expected a table, got " + what_it_is(v),
              "keys " + fmt::format("{}", fmt::join(schema_.children(chosen), ", ")));
    } else {
      const auto segments = split_path(path);
      table_at(segments, segments.size());  // so that an empty user-named table is seen
      walk(*v.as_table(), chosen, path);
    }
  }
}

void Loader::unknown(const toml::node& v, const std::string& pattern, const std::string& concrete,
                     const std::string& name) {
  const auto siblings = schema_.children(pattern);
  std::string hint;
  if (auto near = nearest(name, siblings); !near.empty()) {
    hint = join(concrete, near);
  } else {
    // The key may belong to another section, e.g. ghost_layers written under [mesh].
    std::vector<std::string> leaves;
    for (const auto& key : schema_.keys()) leaves.push_back(split_path(key.path).back());
    if (auto leaf_name = nearest(name, leaves); !leaf_name.empty())
      for (const auto& key : schema_.keys())
        if (split_path(key.path).back() == leaf_name) hint = key.path;
  }
  const std::string what = v.is_table() ? "unknown table" : "unknown key";
  problem(where.at(join(concrete, name)), join(concrete, name),
          hint.empty() ? what : fmt::format("{}; did you mean '{}'?", what, hint),
          fmt::format("{}{}", concrete.empty() ? "sections " : "keys ", fmt::join(siblings, ", ")));
}

bool Loader::number(const KeyDecl& decl, const toml::node& v, const std::string& key, bool integer,
                    std::string_view what, double& x) {
  const Location loc = at(v.source());
  if (integer ? !v.is_integer() : !v.is_number()) {
    problem(loc, key,
            fmt::format("{}expected {}, got {}", what == "value" ? "" : fmt::format("{}: ", what),
                        integer ? "an integer" : "a number", what_it_is(v)),
            accepted_values(decl));
    return false;
  }
  x = v.is_integer() ? static_cast<double>(*v.value<std::int64_t>()) : *v.value<double>();
  // "value 7 is out of range" or "element 2 is 7, out of range".
  auto report = [&](std::string_view trouble, bool needs_is) {
    problem(loc, key,
            what == "value" ? fmt::format("value {} {}{}", x, needs_is ? "is " : "", trouble)
                            : fmt::format("{} is {}, {}", what, x, trouble),
            accepted_values(decl));
    return false;
  };
  if (!std::isfinite(x)) return report("not a finite number", true);
  if (!within_bounds(decl, x))
    return report(decl.integers.empty() ? "out of range" : "not an accepted value", true);
  // Integers are read as int by the code; keep them in its range.
  if (integer && std::abs(x) > 2147483647.0) return report("does not fit a 32-bit integer", false);
  return true;
}

void Loader::leaf(const KeyDecl& decl, const toml::node& v, const std::string& key) {
  const Location loc = at(v.source());
  const std::string accepted = accepted_values(decl);
  auto wrong_type = [&] {
    problem(loc, key, fmt::format("expected {}, got {}", expected_phrase(decl.type), what_it_is(v)),
            accepted);
  };
  from_file_.insert(key);
  double x = 0;
  switch (decl.type) {
    case KeyType::boolean:
      if (!v.is_boolean()) return wrong_type();
      return insert(key, toml::value<bool>(*v.value<bool>()));
    case KeyType::integer:
      if (number(decl, v, key, true, "value", x))
        insert(key, toml::value<std::int64_t>(std::int64_t(x)));
      return;
    case KeyType::real:
      if (number(decl, v, key, false, "value", x)) insert(key, toml::value<double>(x));
      return;
    case KeyType::string:
    case KeyType::choice: {
      if (!v.is_string()) return wrong_type();
      const std::string s = *v.value<std::string>();
      const auto& c = decl.choices;
      if (decl.type == KeyType::choice && std::find(c.begin(), c.end(), s) == c.end()) {
        const auto near = nearest(s, c);
        problem(loc, key,
                near.empty() ? fmt::format("unknown value \"{}\"", s)
                             : fmt::format("unknown value \"{}\"; did you mean \"{}\"?", s, near),
                accepted);
        return;
      }
      return insert(key, toml::value<std::string>(s));
    }
    case KeyType::real3:
    case KeyType::int3:
    case KeyType::real_list: {
      if (!v.is_array()) return wrong_type();
      const auto& in = *v.as_array();
      const bool fixed = decl.type != KeyType::real_list;
      if (fixed ? in.size() != 3 : in.size() < decl.min_size) {
        problem(loc, key,
                fmt::format("expected {}, got {} values", expected_phrase(decl.type), in.size()),
                accepted);
        return;
      }
      const bool integer = decl.type == KeyType::int3;
      toml::array result;
      bool good = true;
      for (std::size_t i = 0; i < in.size(); ++i) {
        if (!number(decl, in[i], key, integer, fmt::format("element {}", i + 1), x)) {
          good = false;
          continue;
        }
        if (integer)
          result.push_back(std::int64_t(x));
        else
          result.push_back(x);
      }
      if (good) insert(key, std::move(result));
      return;
    }
    case KeyType::string_list: {
      if (!v.is_array()) return wrong_type();
      const auto& in = *v.as_array();
      if (in.size() < decl.min_size) {
        problem(loc, key,
                fmt::format("expected at least {} strings, got {}", decl.min_size, in.size()),
                accepted);
        return;
      }
      toml::array result;
      std::set<std::string> seen;
      for (std::size_t i = 0; i < in.size(); ++i) {
        const Location eloc = at(in[i].source());
        if (!in[i].is_string()) {
          problem(eloc, key,
                  fmt::format("element {}: expected a string, got {}", i + 1, what_it_is(in[i])),
                  accepted);
          return;
        }
        const std::string s = *in[i].value<std::string>();
        const auto& c = decl.choices;
        if (!c.empty() && std::find(c.begin(), c.end(), s) == c.end()) {
          problem(eloc, key, fmt::format("element {}: unknown value \"{}\"", i + 1, s), accepted);
          return;
        }
        if (!c.empty() && !seen.insert(s).second) {
          problem(eloc, key, fmt::format("element {}: \"{}\" is repeated", i + 1, s), accepted);
          return;
        }
        result.push_back(s);
      }
      return insert(key, std::move(result));
    }
    case KeyType::real_table: {
      if (!v.is_table()) return wrong_type();
      toml::table result;
      bool good = true;
      for (auto&& [k, e] : *v.as_table()) {
        const std::string entry = join(key, k.str());
        where[entry] = at(k.source());
        if (number(decl, e, entry, false, "value", x))
          result.insert_or_assign(k.str(), x);
        else
          good = false;
      }
      if (good) insert(key, std::move(result));
      return;
    }
  }
}

toml::table& Loader::table_at(const std::vector<std::string>& segments, std::size_t count) {
  toml::table* t = &out;
  for (std::size_t i = 0; i < count; ++i)
    t = t->emplace<toml::table>(segments[i]).first->second.as_table();
  return *t;
}

template <class Node>
void Loader::insert(const std::string& concrete, Node&& node) {
  const auto segments = split_path(concrete);
  table_at(segments, segments.size() - 1)
      .insert_or_assign(segments.back(), std::forward<Node>(node));
}

const toml::node* Loader::lookup(const std::string& concrete) const {
  return find_node(out, concrete);
}

// Concrete paths of a key pattern: wildcard segments take the names of the tables the user wrote.
std::vector<std::string> Loader::expand(const std::string& pattern) const {
  const auto segments = split_path(pattern);
  std::vector<std::string> paths;
  auto rec = [&](auto&& self, std::size_t i, const toml::table* t,
                 const std::string& prefix) -> void {
    if (i + 1 == segments.size()) {
      paths.push_back(join(prefix, segments[i]));
      return;
    }
    if (segments[i] == "*") {
      if (!t) return;
      for (auto&& [k, v] : *t)
        if (v.is_table()) self(self, i + 1, v.as_table(), join(prefix, k.str()));
      return;
    }
    const toml::node* child = t ? t->get(segments[i]) : nullptr;
    if (child && !child->is_table()) return;  // a type problem was already reported
    self(self, i + 1, child ? child->as_table() : nullptr, join(prefix, segments[i]));
  };
  rec(rec, 0, &out, "");
  return paths;
}

// The condition that switches the key off at this concrete path (actual = the value that did
// it, empty when the condition key itself is missing), or nullptr when the key is in use.
const Condition* Loader::failed_condition(const KeyDecl& decl, const std::string& concrete,
                                          std::string& actual, std::string* used) const {
  const auto names = split_path(concrete);
  for (const auto* c : schema_.conditions_for(decl.pattern)) {
    auto segments = split_path(c->key);
    std::string key;
    for (std::size_t i = 0; i < segments.size(); ++i)
      key = join(key, segments[i] == "*" && i < names.size() ? names[i] : segments[i]);
    const toml::node* n = lookup(key);
    actual = n && n->is_string() ? *n->value<std::string>() : std::string();
    if (used) *used = key;
    if (std::find(c->values.begin(), c->values.end(), actual) == c->values.end()) return c;
  }
  return nullptr;
}

Location Loader::nearest_location(std::string concrete) const {
  return nearest_written(where, concrete, file_);
}

void Loader::fill_defaults() {
  for (const auto& decl : schema_.keys()) {
    for (const auto& path : expand(decl.pattern)) {
      std::string actual;
      if (failed_condition(decl, path, actual) || lookup(path)) continue;
      if (from_file_.count(path)) continue;  // written but invalid: already reported
      if (!decl.fallback) {
        problem(nearest_location(path), path,
                fmt::format("required key is missing; expected {}{}", expected_phrase(decl.type),
                            decl.unit == "-" ? "" : " in " + decl.unit),
                accepted_values(decl));
        continue;
      }
      std::visit(
          [&](const auto& value) {
            using T = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::int64_t> ||
                          std::is_same_v<T, double> || std::is_same_v<T, std::string>) {
              insert(path, toml::value<T>(value));
            } else if constexpr (std::is_same_v<T, std::map<std::string, double>>) {
              toml::table t;
              for (const auto& [k, x] : value) t.insert_or_assign(k, x);
              insert(path, std::move(t));
            } else {
              toml::array a;
              for (const auto& x : value) a.push_back(x);
              insert(path, std::move(a));
            }
          },
          *decl.fallback);
    }
  }
}

void Loader::check_conditions() {
  for (const auto& path : from_file_) {
    const KeyDecl* decl = schema_.find(path);
    std::string actual, used;
    const Condition* c = failed_condition(*decl, path, actual, &used);
    if (!c || actual.empty()) continue;
    std::vector<std::string> quoted;
    for (const auto& v : c->values) quoted.push_back('"' + v + '"');
    problem(where.at(path), path, fmt::format("has no effect because {} = \"{}\"", used, actual),
            fmt::format("only when {} is {}", used, fmt::join(quoted, " or ")));
  }
}

void Loader::fail() {
  std::stable_sort(problems_.begin(), problems_.end(), [](const Problem& a, const Problem& b) {
    return std::tie(a.loc.line, a.loc.column) < std::tie(b.loc.line, b.loc.column);
  });
  std::vector<std::string> lines;
  for (auto& p : problems_) lines.push_back(std::move(p.text));
  throw SceneError(std::move(lines));
}

// One override "a.b.c=VALUE" into `root`: VALUE parsed as TOML (a bare word that is not TOML
// becomes a string), its tables created, its source named "--set a.b.c=VALUE" for messages.
void apply_override(toml::table& root, const std::string& setting) {
  const std::string name = "--set " + setting;
  const auto eq = setting.find('=');
  auto trim = [](std::string_view v) {
    const auto b = v.find_first_not_of(" \t"), e = v.find_last_not_of(" \t");
    return b == std::string_view::npos ? std::string() : std::string(v.substr(b, e - b + 1));
  };
  const std::string key = eq == std::string::npos ? "" : trim(setting.substr(0, eq));
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    throw SceneError(
        {fmt::format("{}: expected KEY=VALUE with a dotted scene key, e.g. --set "
                     "time.end=2 or --set flow.scheme=central4",
                     name)});
  const std::string value = trim(setting.substr(eq + 1));
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value, std::string_view(name));
  } catch (const toml::parse_error& e) {
    if (value.empty() || value.find_first_of("'\n") != std::string::npos)
      throw SceneError({fmt::format("{}: the value is not TOML ({})", name, e.description())});
    parsed = toml::parse("v = '" + value + "'", std::string_view(name));
  }
  toml::table* table = &root;
  std::string_view rest = key;
  for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    const std::string segment(rest.substr(0, dot));
    auto [it, inserted] = table->emplace(segment, toml::table{});
    if (!it->second.is_table())
      throw SceneError({fmt::format("{}: '{}' is a value in the scene, not a table", name,
                                    key.substr(0, key.size() - rest.size() + dot))});
    table = it->second.as_table();
    rest.remove_prefix(dot + 1);
  }
  auto it = parsed.begin();
  toml::key leaf(std::string(rest), it->first.source());
  table->erase(leaf.str());  // so that the key, too, names the override as its source
  it->second.visit([&](auto&& v) { table->insert(leaf, std::move(v)); });
}

}  // namespace

Scene parse_scene(std::string_view text, const std::filesystem::path& file, const Schema& schema) {
  return parse_scene(text, file, {}, schema);
}

Scene parse_scene(std::string_view text, const std::filesystem::path& file,
                  const std::vector<std::string>& overrides, const Schema& schema) {
  const std::string name = file.string();
  toml::table parsed;
  try {
    parsed = toml::parse(text, std::string_view(name));
  } catch (const toml::parse_error& e) {
    const Location loc{name, static_cast<int>(e.source().begin.line),
                       static_cast<int>(e.source().begin.column)};
    throw SceneError({fmt::format("{}: TOML syntax error: {}", loc.str(), e.description())});
  }
  for (const auto& setting : overrides) apply_override(parsed, setting);
  Loader loader(schema, name);
  loader.walk(parsed, "", "");
  loader.fill_defaults();
  loader.check_conditions();
  if (!loader.ok()) loader.fail();
  return Scene(file, std::move(loader.out), std::move(loader.where), schema);
}

Scene load_scene(const std::filesystem::path& file, const Schema& schema) {
  return load_scene(file, {}, schema);
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                 const Schema& schema) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError({fmt::format("{}: cannot open the scene file", file.string())});
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), file, overrides, schema);
}

}  // namespace valsalva::scene
