// The stored record of a validation case's last measurement at one level, kept in the
// repository as data: validation/<case>/results/quick.json and full.json. docs/validation.md
// is generated from these records and the cases' README.md (validation/docs.hpp).
//
// A measured record (`valsalva validate CASE [--quick] --record`):
//   {"case", "level": "quick"|"full", "origin": "measured", "command", "date" (UTC, ISO 8601),
//    "commit" (git HEAD of the source tree, "+local changes" when it differs from it),
//    "machine", "report": the run's report.json}
// A record carried over from the hand-written document of earlier sessions (full levels not
// re-run since):
//   {"case", "level", "origin": "carried_over", "command", "date", "commit", "machine",
//    "source": where the numbers were written down, "pass": true|false,
//    "summary": {"metric", "measured", "target", "result"}: the row of the summary table,
//    "tables": [{"title", "columns": [...], "rows": [[...], ...]}]: the documented numbers as
//    they were written, cell by cell}
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace valsalva::validation {

enum class Level { quick, full };
const char* level_name(Level level);

// validation/<case>/results/<level>.json below `case_dir` (the case's folder).
std::filesystem::path record_file(const std::filesystem::path& case_dir, Level level);

// Where and on what a record was measured.
struct RecordOrigin {
  std::string command;
  std::string date;     // UTC, ISO 8601
  std::string commit;   // git HEAD of the source tree, or "unknown"
  std::string machine;  // host, cores, CPU model
};

// The origin of a run now: the date, `git -C source_dir rev-parse HEAD` (with "+local changes"
// when the tracked files differ from HEAD), the host name, core count and CPU model.
RecordOrigin current_origin(const std::filesystem::path& source_dir, const std::string& command);

// A measured record from a run's report (Report::to_json).
nlohmann::ordered_json measured_record(const std::string& case_name, Level level,
                                       const nlohmann::ordered_json& report,
                                       const RecordOrigin& origin);

// Writes `record` to `file` (its folder created), indented, with a final newline.
void write_record(const std::filesystem::path& file, const nlohmann::ordered_json& record);

// The record in `file`, or nothing when there is none; std::runtime_error naming the file when
// it does not parse or lacks a field the documentation needs.
std::optional<nlohmann::ordered_json> read_record(const std::filesystem::path& file);

}  // namespace valsalva::validation
