#include "validation/record.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <thread>

namespace valsalva::validation {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const char* level_name(Level level) {
  return level == Level::quick ? "quick" : "full";
}

fs::path record_file(const fs::path& case_dir, Level level) {
  return case_dir / "results" / (std::string(level_name(level)) + ".json");
}

namespace {

// The first line a shell command prints, without its newline; empty when it fails.
std::string first_line_of(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return "";
  std::array<char, 512> buffer{};
  std::string line;
  if (std::fgets(buffer.data(), buffer.size(), pipe.get())) line = buffer.data();
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line;
}

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

std::string git_commit(const fs::path& source_dir) {
  const auto git = "git -C " + quoted(source_dir);
  const auto head = first_line_of(git + " rev-parse HEAD 2>/dev/null");
  if (head.empty()) return "unknown";
  // Stored records are data, not source: a record rewritten by an earlier --record does not make
  // the source differ from HEAD.
  const auto changed = first_line_of(git + " status --porcelain --untracked-files=no -- . " +
                                     "':(exclude)validation/*/results/*.json' 2>/dev/null");
  return changed.empty() ? head : head + "+local changes";
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown CPU";
}

std::string utc_now() {
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::array<char, 32> text{};
  std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text.data();
}

void require(const json& record, const char* key, const fs::path& file) {
  if (!record.contains(key))
    throw std::runtime_error(fmt::format("{}: the record has no \"{}\"", file.string(), key));
}

}  // namespace

RecordOrigin current_origin(const fs::path& source_dir, const std::string& command) {
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  const auto machine = fmt::format("{}: {} cores, {}", host[0] ? host.data() : "unknown host",
                                   std::thread::hardware_concurrency(), cpu_model());
  return {command, utc_now(), git_commit(source_dir), machine};
}

json measured_record(const std::string& case_name, Level level, const json& report,
                     const RecordOrigin& origin) {
  return {{"case", case_name},         {"level", level_name(level)},
          {"origin", "measured"},      {"command", origin.command},
          {"date", origin.date},       {"commit", origin.commit},
          {"machine", origin.machine}, {"report", report}};
}

void write_record(const fs::path& file, const json& record) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file);
  out << record.dump(2) << "\n";
  if (!out) throw std::runtime_error("could not write the record " + file.string());
}

std::optional<json> read_record(const fs::path& file) {
  if (!fs::exists(file)) return std::nullopt;
  std::ifstream in(file);
  json record;
  try {
    record = json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("{}: not a valid record: {}", file.string(), e.what()));
  }
  for (const char* key : {"case", "level", "origin", "command", "date", "commit", "machine"})
    require(record, key, file);
  const auto origin = record.at("origin").get<std::string>();
  if (origin == "measured") {
    require(record, "report", file);
    if (!record.at("report").contains("metrics"))
      throw std::runtime_error(file.string() + ": the record's report has no \"metrics\"");
  } else if (origin == "carried_over") {
    for (const char* key : {"source", "pass", "summary", "tables"}) require(record, key, file);
  } else {
    throw std::runtime_error(fmt::format(
        "{}: origin \"{}\" is neither \"measured\" nor \"carried_over\"", file.string(), origin));
  }
  return record;
}

}  // namespace valsalva::validation
