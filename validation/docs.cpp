#include "validation/docs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "validation/case.hpp"
#include "validation/docs_tables.hpp"
#include "validation/record.hpp"

namespace valsalva::validation {

namespace fs = std::filesystem;

namespace {

constexpr const char* results_marker = "<!-- results -->";

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A README's text below its title line ("# ..."), headings one level deeper (the document's
// sections are "##"), outside code fences.
std::vector<std::string> body_of(const fs::path& file) {
  auto lines = lines_of(file);
  std::size_t first = 0;
  if (!lines.empty() && lines[0].rfind("# ", 0) == 0) first = 1;
  while (first < lines.size() && lines[first].empty()) ++first;
  std::vector<std::string> body(lines.begin() + static_cast<std::ptrdiff_t>(first), lines.end());
  while (!body.empty() && body.back().empty()) body.pop_back();
  bool fenced = false;
  for (auto& line : body) {
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (!fenced && line.rfind('#', 0) == 0) line = "#" + line;
  }
  return body;
}

std::string title_of(const fs::path& file, const std::string& fallback) {
  const auto lines = lines_of(file);
  if (!lines.empty() && lines[0].rfind("# ", 0) == 0) return lines[0].substr(2);
  return fallback;
}

void write_lines(std::ostream& out, const std::vector<std::string>& lines, std::size_t from,
                 std::size_t to) {
  for (std::size_t i = from; i < to; ++i) out << lines[i] << "\n";
}

struct CaseRecords {
  std::optional<nlohmann::ordered_json> full, quick;
};

CaseRecords records_of(const fs::path& case_dir) {
  return {read_record(record_file(case_dir, Level::full)),
          read_record(record_file(case_dir, Level::quick))};
}

void write_summary(std::ostream& out, const std::vector<CaseDoc>& cases,
                   const std::vector<CaseRecords>& records) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto link = fmt::format("[{}](#{})", cases[i].name, cases[i].name);
    bool any = false;
    for (const auto* record : {&records[i].full, &records[i].quick}) {
      if (!*record) continue;
      any = true;
      const auto cells = summary_cells(**record);  // metric, measured, target, result, date
      rows.push_back({link, cells[0], cells[1], cells[2], cells[3],
                      (*record)->at("level").get<std::string>(), cells[4]});
    }
    if (!any) rows.push_back({link, "not measured", "-", "-", "no record", "-", "-"});
  }
  write_md_table(
      out, {"case", "metric", "measured", "reference / target", "result", "level", "date"}, rows);
}

void write_results(std::ostream& out, const CaseDoc& c, const CaseRecords& records) {
  out << "### Results\n\n";
  for (const auto& [record, level] :
       {std::pair{&records.full, Level::full}, std::pair{&records.quick, Level::quick}}) {
    if (*record) {
      write_record_results(out, **record);
      continue;
    }
    out << fmt::format(
        "**{} level**: not measured (no record validation/{}/results/{}.json; "
        "`valsalva validate {}{} --record` makes one).\n\n",
        level == Level::full ? "Full" : "Quick", c.name, level_name(level), c.name,
        level == Level::quick ? " --quick" : "");
  }
}

void write_case(std::ostream& out, const fs::path& validation_dir, const CaseDoc& c,
                const CaseRecords& records) {
  out << "## " << c.name << "\n\n";
  if (!c.description.empty()) out << "*" << c.description << "*\n\n";
  const auto readme = validation_dir / c.name / "README.md";
  if (!fs::exists(readme)) {
    out << fmt::format("No README.md in validation/{}/ yet.\n\n", c.name);
    write_results(out, c, records);
    return;
  }
  const auto body = body_of(readme);
  const auto marker = std::find(body.begin(), body.end(), results_marker);
  // The text before the marker and after it, without the blank lines around the marker.
  std::size_t before = static_cast<std::size_t>(marker - body.begin());
  std::size_t after = before + 1;
  while (before > 0 && body[before - 1].empty()) --before;
  while (after < body.size() && body[after].empty()) ++after;
  write_lines(out, body, 0, before);
  if (before > 0) out << "\n";
  write_results(out, c, records);
  if (after < body.size()) {
    write_lines(out, body, after, body.size());
    out << "\n";
  }
}

}  // namespace

std::vector<CaseDoc> registered_case_docs() {
  std::vector<CaseDoc> docs;
  for (const auto& c : all_cases()) docs.push_back({c.name, c.description});
  return docs;
}

void write_validation_docs(std::ostream& out, const fs::path& validation_dir,
                           std::vector<CaseDoc> cases) {
  std::sort(cases.begin(), cases.end(),
            [](const CaseDoc& a, const CaseDoc& b) { return a.name < b.name; });
  std::vector<CaseRecords> records;
  for (const auto& c : cases) records.push_back(records_of(validation_dir / c.name));

  out << "# Validation status\n\n"
         "<!-- Generated by validation::write_validation_docs from validation/README.md,\n"
         "     validation/<case>/README.md, validation/<case>/results/*.json and\n"
         "     validation/notes/*.md. Do not edit; regenerate with:\n"
         "     build/bin/valsalva docs-validation > docs/validation.md -->\n\n";
  const auto intro = body_of(validation_dir / "README.md");
  write_lines(out, intro, 0, intro.size());
  if (!intro.empty()) out << "\n";
  out << "## Summary\n\n";
  write_summary(out, cases, records);
  out << "\n";
  for (std::size_t i = 0; i < cases.size(); ++i)
    write_case(out, validation_dir, cases[i], records[i]);

  std::vector<fs::path> notes;
  if (fs::is_directory(validation_dir / "notes"))
    for (const auto& entry : fs::directory_iterator(validation_dir / "notes"))
      if (entry.path().extension() == ".md") notes.push_back(entry.path());
  std::sort(notes.begin(), notes.end());
  for (const auto& note : notes) {
    out << "## " << title_of(note, note.stem().string()) << "\n\n";
    const auto body = body_of(note);
    write_lines(out, body, 0, body.size());
    out << "\n";
  }
}

}  // namespace valsalva::validation
