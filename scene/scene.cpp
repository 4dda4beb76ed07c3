#include "scene/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace valsalva::scene {
namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "\n") + l;
  return out;
}

template <class T>
constexpr KeyType key_type_of() {
  if constexpr (std::is_same_v<T, bool>)
    return KeyType::boolean;
  else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::int64_t>)
    return KeyType::integer;
  else if constexpr (std::is_same_v<T, double>)
    return KeyType::real;
  else if constexpr (std::is_same_v<T, std::string>)
    return KeyType::string;
  else if constexpr (std::is_same_v<T, std::array<double, 3>>)
    return KeyType::real3;
  else if constexpr (std::is_same_v<T, std::array<int, 3>>)
    return KeyType::int3;
  else if constexpr (std::is_same_v<T, std::vector<std::string>>)
    return KeyType::string_list;
  else if constexpr (std::is_same_v<T, std::vector<double>>)
    return KeyType::real_list;
  else
    return KeyType::real_table;
}

}  // namespace

const toml::node* find_node(const toml::table& root, std::string_view path) {
  const toml::node* n = &root;
  for (const auto& s : split_path(path)) {
    n = n->is_table() ? n->as_table()->get(s) : nullptr;
    if (!n) return nullptr;
  }
  return n;
}

Location nearest_written(const std::map<std::string, Location>& where, std::string_view path,
                         const std::string& file) {
  std::string p(path);
  while (!p.empty()) {
    if (auto it = where.find(p); it != where.end()) return it->second;
    const auto dot = p.rfind('.');
    p = dot == std::string::npos ? std::string() : p.substr(0, dot);
  }
  return {file, 1, 1};
}

SceneError::SceneError(std::vector<std::string> problems)
    : std::runtime_error(join_lines(problems)), problems_(std::move(problems)) {}

std::string Location::str() const {
  return fmt::format("{}:{}:{}", file, line, column);
}

std::string format_problem(const Location& at, std::string_view key, std::string_view problem,
                           std::string_view accepted) {
  if (accepted.empty()) return fmt::format("{}: key '{}': {}", at.str(), key, problem);
  return fmt::format("{}: key '{}': {} (accepted: {})", at.str(), key, problem, accepted);
}

Scene::Scene(std::filesystem::path file, toml::table resolved,
             std::map<std::string, Location> where, const Schema& schema)
    : file_(std::move(file)),
      table_(std::move(resolved)),
      where_(std::move(where)),
      schema_(&schema) {}

const toml::node& Scene::node(std::string_view key, KeyType expected) const {
  const KeyDecl* decl = schema_->find(key);
  if (!decl) throw std::logic_error(fmt::format("scene key '{}' is not declared", key));
  const bool same =
      decl->type == expected || (expected == KeyType::string && decl->type == KeyType::choice);
  if (!same)
    throw std::logic_error(fmt::format("scene key '{}' is declared as {}, read as {}", key,
                                       type_name(decl->type), type_name(expected)));
  const toml::node* n = find_node(table_, key);
  if (!n)
    throw std::logic_error(
        fmt::format("scene key '{}' is not in the scene {} (switched off by a condition?)", key,
                    file_.string()));
  return *n;
}

template <SceneValue T>
T Scene::get(std::string_view key) const {
  const toml::node& n = node(key, key_type_of<T>());
  if constexpr (std::is_same_v<T, int>) {
    return static_cast<int>(*n.value<std::int64_t>());  // range checked when loading
  } else if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::int64_t> ||
                       std::is_same_v<T, double> || std::is_same_v<T, std::string>) {
    return *n.value<T>();
  } else if constexpr (std::is_same_v<T, std::array<double, 3>>) {
    const auto& a = *n.as_array();
    return {*a[0].value<double>(), *a[1].value<double>(), *a[2].value<double>()};
  } else if constexpr (std::is_same_v<T, std::array<int, 3>>) {
    const auto& a = *n.as_array();
    return {static_cast<int>(*a[0].value<std::int64_t>()),
            static_cast<int>(*a[1].value<std::int64_t>()),
            static_cast<int>(*a[2].value<std::int64_t>())};
  } else if constexpr (std::is_same_v<T, std::vector<std::string>> ||
                       std::is_same_v<T, std::vector<double>>) {
    T out;
    for (const auto& e : *n.as_array()) out.push_back(*e.template value<typename T::value_type>());
    return out;
  } else {
    T out;
    for (auto&& [k, v] : *n.as_table()) out[std::string(k.str())] = *v.template value<double>();
    return out;
  }
}

template bool Scene::get<bool>(std::string_view) const;
template int Scene::get<int>(std::string_view) const;
template std::int64_t Scene::get<std::int64_t>(std::string_view) const;
template double Scene::get<double>(std::string_view) const;
template std::string Scene::get<std::string>(std::string_view) const;
template std::array<double, 3> Scene::get<std::array<double, 3>>(std::string_view) const;
template std::array<int, 3> Scene::get<std::array<int, 3>>(std::string_view) const;
template std::vector<std::string> Scene::get<std::vector<std::string>>(std::string_view) const;
template std::vector<double> Scene::get<std::vector<double>>(std::string_view) const;
template std::map<std::string, double> Scene::get<std::map<std::string, double>>(
    std::string_view) const;

bool Scene::has(std::string_view key) const {
  return find_node(table_, key) != nullptr;
}

bool Scene::is_set(std::string_view key) const {
  return where_.count(std::string(key)) > 0;
}

std::vector<std::string> Scene::names(std::string_view table) const {
  const toml::node* n = find_node(table_, table);
  std::vector<std::string> out;
  if (!n || !n->is_table()) return out;
  for (auto&& [k, v] : *n->as_table()) out.emplace_back(k.str());
  // File order, not the alphabetical order of the TOML table.
  auto line_of = [&](const std::string& name) {
    const auto it = where_.find(fmt::format("{}.{}", table, name));
    return it == where_.end() ? std::pair{std::numeric_limits<int>::max(), 0}
                              : std::pair{it->second.line, it->second.column};
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const auto& a, const auto& b) { return line_of(a) < line_of(b); });
  return out;
}

std::filesystem::path Scene::path(std::string_view key) const {
  const std::filesystem::path p = get<std::string>(key);
  if (p.is_absolute()) return p;
  return (file_.parent_path() / p).lexically_normal();
}

Location Scene::location(std::string_view key) const {
  return nearest_written(where_, key, file_.string());
}

SceneError Scene::error(std::string_view key, std::string_view problem,
                        std::string_view accepted) const {
  return SceneError({format_problem(location(key), key, problem, accepted)});
}

std::string Scene::resolved() const {
  std::ostringstream out;
  out << "# " << file_.string() << " with every default filled in (valsalva)\n" << table_ << "\n";
  return out.str();
}

}  // namespace valsalva::scene
