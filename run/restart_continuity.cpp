#include "run/restart_continuity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/comm.hpp"
#include "io/hdf5_file.hpp"

namespace valsalva::run {

namespace fs = std::filesystem;

namespace {

// Dotted path -> TOML text of every value of a table.
void flatten(const toml::table& table, const std::string& prefix,
             std::map<std::string, std::string>& out) {
  for (const auto& [key, node] : table) {
    const std::string path =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const auto* sub = node.as_table()) {
      flatten(*sub, path, out);
    } else if (const auto* real = node.as_floating_point()) {
      out[path] =
          fmt::format("{}", real->get());  // shortest round trip: 0.1, not 0.10000000000000001
    } else {
      std::ostringstream text;
      node.visit([&](const auto& v) { text << v; });
      out[path] = text.str();
    }
  }
}

// The time-step rule: a smaller step lets a run go on past a stretch that diverged, from its
// last good checkpoint. The continuation is then not bitwise the one the old rule would make.
bool is_step_rule(const std::string& key) {
  static const std::regex rule("time\\.(cfl|fourier|dt)");
  return std::regex_match(key, rule);
}

bool may_change(const std::string& key) {
  // wall_shear.start_time: a later one starts the averaging window afresh
  // (analysis::WallShearRecorder::restore).
  static const std::regex allowed(
      "time\\.(end|max_steps)|output\\.(interval|interval_unit|checkpoint_every_steps|"
      "checkpoint_every_minutes|checkpoint_keep|checkpoint_on_signal)|run\\..*|partition\\..*|"
      "sample\\..*|wall_shear\\.start_time");
  return std::regex_match(key, allowed) || is_step_rule(key);
}

struct KeyChange {
  std::string key, before, after;
};

// Every key whose value differs between the recorded scene and `scene`; an error message when the
// recorded scene does not parse.
std::string scene_changes(const fs::path& recorded, const scene::Scene& scene,
                          std::vector<KeyChange>& changes) {
  toml::table old_table;
  try {
    old_table = toml::parse_file(recorded.string());
  } catch (const toml::parse_error& e) {
    return fmt::format("the recorded scene '{}' does not parse: {}", recorded.string(),
                       e.description());
  }
  // A run recorded by an older valsalva lacks the keys added since; resolving its scene with
  // today's schema fills them with their defaults, so only real changes are reported. A
  // recorded scene today's schema refuses is compared as written.
  std::ostringstream recorded_text;
  recorded_text << old_table;
  try {
    old_table = scene::parse_scene(recorded_text.str(), scene.file()).table();
  } catch (const std::exception&) {
  }
  std::map<std::string, std::string> before, after;
  flatten(old_table, "", before);
  flatten(scene.table(), "", after);
  auto value = [](const std::map<std::string, std::string>& m, const std::string& k) {
    const auto it = m.find(k);
    return it == m.end() ? std::string("(absent)") : it->second;
  };
  std::map<std::string, bool> keys;
  for (const auto& [k, v] : before) keys[k] = true;
  for (const auto& [k, v] : after) keys[k] = true;
  for (const auto& [k, unused] : keys)
    if (value(before, k) != value(after, k))
      changes.push_back({k, value(before, k), value(after, k)});
  return {};
}

}  // namespace

std::string restart_scene_change(const fs::path& recorded, const scene::Scene& scene) {
  std::vector<KeyChange> all;
  if (auto error = scene_changes(recorded, scene, all); !error.empty()) return error;
  std::vector<std::string> changes;
  for (const auto& c : all)
    if (!may_change(c.key))
      changes.push_back(fmt::format("{} = {} in the run, {} in {}", c.key, c.before, c.after,
                                    scene.file().string()));
  if (changes.empty()) return {};
  std::string message = fmt::format(
      "restart: the scene differs from the run's ({}) in keys a restart must not change "
      "(only time.end, time.max_steps, the time-step rule time.cfl, time.fourier and time.dt, "
      "output intervals and checkpoints, run.*, partition.*, [sample.*] sections and "
      "wall_shear.start_time may change):",
      recorded.string());
  for (const auto& c : changes) message += "\n  " + c;
  return message;
}

std::string restart_step_rule_change(const fs::path& recorded, const scene::Scene& scene) {
  std::vector<KeyChange> all;
  if (!scene_changes(recorded, scene, all).empty()) return {};
  std::string message;
  for (const auto& c : all)
    if (is_step_rule(c.key))
      message +=
          fmt::format("{}{} {} -> {}", message.empty() ? "" : ", ", c.key, c.before, c.after);
  return message;
}

std::vector<fs::path> superseded_restart_outputs(const fs::path& dir, std::int64_t step) {
  static const std::regex fields("fields_restart_([0-9]{9})(\\.xmf|_mesh\\.h5|_[0-9]{6}\\.h5)");
  static const std::regex solids(".+_restart_([0-9]{9})(\\.xmf|_[0-9]+\\.h5|_mesh\\.h5)");
  std::vector<fs::path> found;
  auto scan = [&](const fs::path& folder, const std::regex& pattern) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return;
    for (const auto& entry : fs::directory_iterator(folder)) {
      std::smatch m;
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && std::regex_match(name, m, pattern) && std::stoll(m[1]) >= step)
        found.push_back(entry.path());
    }
  };
  scan(dir, fields);
  scan(dir / "structures", solids);
  std::sort(found.begin(), found.end());
  return found;
}

void continue_in_place(const fs::path& dir, const scene::Scene& scene, std::int64_t step,
                       double time, double dt, const std::vector<std::string>& series,
                       const core::Comm& comm) {
  std::string error;
  if (comm.root()) {
    try {
      // A name the table does not know would be continued uncut (its rows after the checkpoint
      // repeated): a programming error, refused rather than skipped.
      for (const auto& name : series)
        if (std::none_of(io::appended_series().begin(), io::appended_series().end(),
                         [&](const io::AppendedSeries& s) { return s.file == name; }))
          throw std::logic_error(fmt::format(
              "restart: '{}' is not among the appended series that a restart cuts back", name));
      for (const auto& s : io::appended_series()) {
        if (std::find(series.begin(), series.end(), s.file) == series.end()) continue;
        const fs::path file = dir / s.file;
        if (!fs::exists(file))
          throw std::runtime_error(fmt::format(
              "restart: '{}' is missing: the run wrote it and the restart would continue it "
              "without its earlier rows; restore it, or restart into another --out",
              file.string()));
        if (const auto cut = io::truncate_series(file, s.by_step, step, time, dt); cut > 0)
          fmt::print("restart: {} rows of {} after the checkpoint removed\n", cut, s.file);
      }
      for (const auto& p : superseded_restart_outputs(dir, step)) {
        fs::remove(p);
        fmt::print("restart: {} (an earlier restart from this or a later checkpoint) removed\n",
                   p.string());
      }
      const fs::path record = dir / fmt::format("resolved_scene_restart_{:09d}.toml", step);
      std::ofstream out(record, std::ios::binary | std::ios::trunc);
      out << scene.resolved();
      out.close();
      if (!out)
        throw std::runtime_error(fmt::format("restart: cannot write '{}'", record.string()));
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  io::h5::settle(comm.get(), error);
}

}  // namespace valsalva::run
