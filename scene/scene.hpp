// A validated scene: the TOML file with every default filled in, typed getters, and the source
// location of every key so that later checks (a boundary patch the mesh lacks, say) can also
// point at FILE:LINE:COLUMN.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "scene/scene_schema.hpp"

namespace valsalva::scene {

// Every problem found in a scene, one line each, formatted
//   FILE:LINE:COLUMN: key 'a.b.c': problem (accepted: ...)
// what() joins them with newlines; problems() lists them in file order.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

struct Location {
  std::string file;
  int line = 1;
  int column = 1;
  std::string str() const;  // "FILE:LINE:COLUMN"
};

// "FILE:LINE:COLUMN: key 'KEY': PROBLEM (accepted: ACCEPTED)"; the parenthesis only when
// `accepted` is not empty.
std::string format_problem(const Location& at, std::string_view key, std::string_view problem,
                           std::string_view accepted = {});

// The C++ types a scene value can be read as, one per KeyType.
template <class T>
concept SceneValue = std::is_same_v<T, bool> || std::is_same_v<T, int> ||
    std::is_same_v<T, std::int64_t> || std::is_same_v<T, double> ||
    std::is_same_v<T, std::string> || std::is_same_v<T, std::array<double, 3>> ||
    std::is_same_v<T, std::array<int, 3>> || std::is_same_v<T, std::vector<std::string>> ||
    std::is_same_v<T, std::vector<double>> || std::is_same_v<T, std::map<std::string, double>>;

class Scene {
 public:
  Scene(std::filesystem::path file, toml::table resolved, std::map<std::string, Location> where,
        const Schema& schema);

  // Value of a key (set in the file or defaulted). Asking for an undeclared key, a key that is
  // absent (e.g. [mesh.pipe] keys when mesh.source = "box") or with a C++ type that does not
  // match its declared type is a programming error: std::logic_error.
  //   bool: boolean; int, int64_t: integer; double: real; std::string: string, choice;
  //   array<double,3>: real3; array<int,3>: int3; vector<string>: string_list;
  //   vector<double>: real_list; map<string,double>: real_table.
  template <SceneValue T>
  T get(std::string_view key) const;

  bool has(std::string_view key) const;     // present after defaults were filled
  bool is_set(std::string_view key) const;  // written in the scene file itself
  // Names of the user-named tables below `table`, e.g. names("mesh.periodic") -> {"x", "y"},
  // in the order of the file.
  std::vector<std::string> names(std::string_view table) const;
  // A string key holding a file name, resolved relative to the scene file's folder.
  std::filesystem::path path(std::string_view key) const;

  // Where a key (or table) was written; for a defaulted key, its nearest written parent table,
  // else line 1 of the file.
  Location location(std::string_view key) const;
  // An error in the scene format for checks done by other modules, e.g.
  //   throw scene.error("mesh.periodic.x.master", "patch 'left' is not in the mesh", "bottom,
  //   top");
  SceneError error(std::string_view key, std::string_view problem,
                   std::string_view accepted = {}) const;

  // The whole scene as TOML with all defaults filled; parsing it gives the same scene.
  std::string resolved() const;
  const toml::table& table() const { return table_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  const toml::node& node(std::string_view key, KeyType expected) const;
  std::filesystem::path file_;
  toml::table table_;
  std::map<std::string, Location> where_;  // concrete path -> location, only keys in the file
  const Schema* schema_;
};

// Helpers shared by the loader and Scene. The node at a dotted path, or nullptr:
const toml::node* find_node(const toml::table& root, std::string_view path);
// Where `path` or its nearest parent was written, else line 1 of `file`.
Location nearest_written(const std::map<std::string, Location>& where, std::string_view path,
                         const std::string& file);

// Reads, validates and resolves a scene file. Throws SceneError listing every problem: TOML
// syntax, unknown keys (with the nearest declared key), wrong types, values out of range or not
// among the accepted ones, missing required keys, keys that have no effect under a condition.
Scene load_scene(const std::filesystem::path& file, const Schema& schema = scene_schema());
// The same with overrides "KEY=VALUE" (`valsalva run --set`, validation levels) applied to the
// file's table before it is checked: VALUE is TOML (a bare word that is not TOML is a string),
// and a problem with an override is reported at "--set KEY=VALUE".
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                 const Schema& schema = scene_schema());
// The same from text; `file` names it in messages and anchors relative paths.
Scene parse_scene(std::string_view text, const std::filesystem::path& file,
                  const Schema& schema = scene_schema());
Scene parse_scene(std::string_view text, const std::filesystem::path& file,
                  const std::vector<std::string>& overrides, const Schema& schema = scene_schema());

}  // namespace valsalva::scene
