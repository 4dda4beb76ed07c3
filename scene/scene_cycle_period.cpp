#include "scene/scene_cycle_period.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/waveform_table.hpp"

namespace valsalva::scene {

namespace {

struct PeriodicTable {
  std::string key;  // boundary.<patch>.file, .pressure_file, .elastance_file or forcing.file
  double period;    // t_last - t_first [s]
};

// The boundary and forcing tables whose last value repeats the first (io/waveform_table.cpp's
// rule).
std::vector<PeriodicTable> periodic_tables(const Scene& scene) {
  std::vector<std::string> keys;
  for (const auto& patch : scene.names("boundary"))
    for (const char* suffix : {".file", ".pressure_file", ".elastance_file"})
      keys.push_back("boundary." + patch + suffix);
  keys.push_back("forcing.file");
  std::vector<PeriodicTable> out;
  for (const auto& key : keys) {
    if (!scene.has(key)) continue;
    const auto table = io::read_waveform_table(scene.path(key));
    double largest = 0;
    for (double q : table.q) largest = std::max(largest, std::abs(q));
    if (std::abs(table.q.back() - table.q.front()) <= 1e-6 * largest)
      out.push_back({key, table.t.back() - table.t.front()});
  }
  return out;
}

void check_period(const Scene& scene, const std::string& period_key,
                  const std::vector<PeriodicTable>& tables) {
  const double period = scene.get<double>(period_key);
  for (const auto& t : tables) {
    const double ratio = period / t.period;
    const double whole = std::round(ratio);
    if (whole >= 1 && std::abs(ratio - whole) <= 1e-6 * ratio) continue;
    throw scene.error(
        period_key,
        fmt::format("{:g} s is not a whole number of periods of the table '{}' ({} = one "
                    "period of {:g} s): the cycles would drift against the imposed waveform",
                    period, scene.path(t.key).string(), t.key, t.period),
        fmt::format("{:g} s or a whole multiple of it", t.period));
  }
}

}  // namespace

void check_cycle_periods(const Scene& scene) {
  const auto tables = periodic_tables(scene);
  if (tables.empty()) return;
  for (const auto& name : scene.names("statistics"))
    if (scene.get<double>("statistics." + name + ".period") > 0)
      check_period(scene, "statistics." + name + ".period", tables);
}

}  // namespace valsalva::scene
