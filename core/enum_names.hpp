// String <-> enum for the options whose scene value is a name (flow.scheme, initial.type,
// partition.method, mesh.box.cell_type, time.scheme): an enum class with the values 0, 1, ...
// in the order of a table of names. Each option declares its names / to_string / parse
// functions next to the enum and defines them in its .cpp from one constexpr EnumNames table:
//   constexpr core::EnumNames<PartitionMethod, 2> kMethods{{"metis", "block"}, "partition method"};
//   VALSALVA_ENUM_NAMES(PartitionMethod, kMethods, partition_method_names, to_string,
//                       parse_partition_method)
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace valsalva::core {

template <class Enum, std::size_t N>
struct EnumNames {
  std::array<std::string_view, N> names;  // names[i] is the name of Enum(i)
  std::string_view what;  // the start of the error message, e.g. "flow: time scheme"

  std::string name(Enum value) const {
    return std::string(names.at(static_cast<std::size_t>(value)));
  }

  // The names as strings, for the scene schema's accepted values and command-line checks (built
  // once per EnumNames type: one table per enum).
  const std::vector<std::string>& list() const {
    static const std::vector<std::string> all(names.begin(), names.end());
    return all;
  }

  // Throws std::invalid_argument "<what> '<name>' is not one of <names, comma-separated>".
  Enum parse(std::string_view name) const {
    for (std::size_t i = 0; i < N; ++i)
      if (names[i] == name) return static_cast<Enum>(i);
    std::string accepted;
    for (const auto n : names) accepted += (accepted.empty() ? "" : ", ") + std::string(n);
    throw std::invalid_argument(std::string(what) + " '" + std::string(name) + "' is not one of " +
                                accepted);
  }
};

}  // namespace valsalva::core

// Defines `const std::vector<std::string>& names_fn()`, `std::string to_string_fn(Enum)` and
// `Enum parse_fn(std::string_view)` from the EnumNames `table`.
#define VALSALVA_ENUM_NAMES(Enum, table, names_fn, to_string_fn, parse_fn) \
  const std::vector<std::string>& names_fn() {                             \
    return table.list();                                                   \
  }                                                                        \
  std::string to_string_fn(Enum value) {                                   \
    return table.name(value);                                              \
  }                                                                        \
  Enum parse_fn(std::string_view name) {                                   \
    return table.parse(name);                                              \
  }
