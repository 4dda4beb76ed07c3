// Declarations of every scene key: dotted path, type, default (or required), unit, accepted
// values and a one-line doc. Each module declares its keys once, in scene/scene_keys_<module>.cpp;
// scene_schema() gathers them into the one registry that validates scenes and generates
// docs/scenes.md (same habit as deal.II's ParameterHandler: declare once, reject the rest).
//
// A path segment written "<label>" (or "*") stands for any table name chosen by the user, e.g.
// "boundary.<patch>.type" accepts [boundary.inlet] type = "...". Keys declared under such a
// segment are filled with defaults, and checked for being required, in every table the user wrote.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace valsalva::scene {

enum class KeyType {
  boolean,
  integer,
  real,
  string,
  choice,       // a string from a fixed list
  real3,        // array of 3 floats
  int3,         // array of 3 integers
  string_list,  // array of strings (optionally each from a fixed list, no repeats)
  real_list,    // array of floats of any length
  real_table,   // table of user-named floats, e.g. { a = 1.0, b = 2.0 }
};

using KeyValue = std::variant<bool, std::int64_t, double, std::string, std::array<double, 3>,
                              std::array<std::int64_t, 3>, std::vector<std::string>,
                              std::vector<double>, std::map<std::string, double>>;

struct Bound {
  double value = 0;
  bool inclusive = true;
};

// One declared key. The setters return *this so declarations read as one statement.
struct KeyDecl {
  std::string path;     // as declared, e.g. "boundary.<patch>.type" (shown in docs and errors)
  std::string pattern;  // wildcard segments normalised to "*", e.g. "boundary.*.type"
  KeyType type = KeyType::real;
  std::optional<KeyValue> fallback;  // the default; empty for required keys
  bool is_required = false;
  std::string default_note;  // replaces the literal default in docs, e.g. "runs/<scene stem>"
  std::string unit;          // SI unit or "-"
  std::string text;          // one-line doc
  std::vector<std::string> choices;    // choice: accepted values; string_list: accepted elements
  std::optional<Bound> lower, upper;   // numbers, element-wise for arrays and tables
  std::size_t min_size = 0;            // real_list / string_list
  std::vector<std::int64_t> integers;  // integer: the only accepted values, when not empty

  KeyDecl& def(bool v);
  KeyDecl& def(int v);
  KeyDecl& def(std::int64_t v);
  KeyDecl& def(double v);
  KeyDecl& def(const char* v);
  KeyDecl& def(std::string v);
  KeyDecl& def(std::array<double, 3> v);
  KeyDecl& def(std::array<int, 3> v);
  KeyDecl& def(std::vector<std::string> v);
  KeyDecl& def(std::vector<double> v);
  KeyDecl& def(std::map<std::string, double> v);
  KeyDecl& required();
  KeyDecl& note(std::string v);  // documents a default that the code computes (see run.output_dir)
  KeyDecl& unit_of(std::string v);
  KeyDecl& doc(std::string v);
  KeyDecl& values(std::vector<std::string> v);
  KeyDecl& at_least(double v);
  KeyDecl& above(double v);
  KeyDecl& at_most(double v);
  KeyDecl& below(double v);
  KeyDecl& in_range(double lo, double hi);
  KeyDecl& one_of(std::vector<std::int64_t> v);  // integer keys: a list, not a range
  KeyDecl& at_least_size(std::size_t n);
};

// A section (table) and its doc line; docs/scenes.md has one table of keys per section.
struct SectionDecl {
  std::string path;
  std::string pattern;
  std::string text;
};

// Keys under `prefix` (a section or one key) are used only when the choice/string key `key` has
// one of `values`; otherwise no default is filled and setting them is an error, so a scene never
// carries keys that silently do nothing. Wildcards in `key` take the names of the checked path.
struct Condition {
  std::string prefix;    // pattern
  std::string key;       // pattern
  std::string key_path;  // as declared, for docs
  std::vector<std::string> values;
};

class Schema {
 public:
  void section(std::string path, std::string doc);
  KeyDecl& boolean(std::string path);
  KeyDecl& integer(std::string path);
  KeyDecl& real(std::string path);
  KeyDecl& string(std::string path);
  KeyDecl& choice(std::string path, std::vector<std::string> values);
  KeyDecl& real3(std::string path);
  KeyDecl& int3(std::string path);
  KeyDecl& string_list(std::string path);
  KeyDecl& real_list(std::string path);
  KeyDecl& real_table(std::string path);
  void when(std::string prefix, std::string key, std::vector<std::string> values);

  // Throws std::logic_error on a bad declaration: duplicate or undeclared-section keys, keys
  // with neither default nor required, defaults outside their own accepted values, conditions
  // on undeclared keys. scene_schema() calls it; tests call it on their own schemas.
  void check() const;

  const std::vector<KeyDecl>& keys() const { return keys_; }
  const std::vector<SectionDecl>& sections() const { return sections_; }
  const std::vector<Condition>& conditions() const { return conditions_; }

  // The key whose pattern matches a concrete path ("boundary.inlet.type"), or nullptr.
  const KeyDecl* find(std::string_view concrete) const;
  const SectionDecl* find_section(std::string_view concrete) const;
  // True if `pattern` is a declared key or a table on the way to one ("mesh", "boundary.*").
  bool is_key(std::string_view pattern) const;
  bool is_table(std::string_view pattern) const;
  // Names (last segments) declared directly below a table pattern, for error messages.
  std::vector<std::string> children(std::string_view table_pattern) const;
  // Conditions that apply to a key or section pattern (its own and those of its prefixes).
  std::vector<const Condition*> conditions_for(std::string_view pattern) const;

 private:
  KeyDecl& add(std::string path, KeyType type);
  std::vector<KeyDecl> keys_;
  std::vector<SectionDecl> sections_;
  std::vector<Condition> conditions_;
};

// The registry of every scene key of valsalva (built once, on first use).
const Schema& scene_schema();

// Helpers shared by validation and docs.
std::string normalise_pattern(std::string_view path);  // "<x>" segments -> "*"
std::vector<std::string> split_path(std::string_view path);
bool is_wildcard(std::string_view segment);
bool pattern_matches(std::string_view pattern, std::string_view concrete);
bool within_bounds(const KeyDecl& key, double x);  // bounds (and one_of list) of the key
std::string type_name(KeyType type);               // "float", "int[3]", ...
std::string accepted_values(const KeyDecl& key);   // "> 0", "\"box\", \"gmsh\"", "any"
std::string format_value(const KeyValue& value);   // TOML literal: 1.0, "hexa", [1, 2, 3]
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace valsalva::scene
