// docs/validation.md is generated from the cases' README.md and stored records
// (validation/docs.hpp); the first test fails when the committed file differs from what they
// generate, and says how to regenerate it. The others check the generator on a made-up tree.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "validation/case.hpp"
#include "validation/docs.hpp"
#include "validation/record.hpp"

namespace fs = std::filesystem;
using namespace valsalva::validation;
using json = nlohmann::ordered_json;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

std::string generate(const fs::path& dir, const std::vector<CaseDoc>& cases) {
  std::ostringstream out;
  write_validation_docs(out, dir, cases);
  return out.str();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A scratch validation folder, removed at the end of the test.
struct ScratchDir {
  fs::path path = fs::temp_directory_path() / ("valsalva_docs_" + std::to_string(::getpid()));
  ScratchDir() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() { fs::remove_all(path); }
};

json report_of(const Report& r) {
  return r.to_json("alpha", 2, 12.3);
}

}  // namespace

TEST_CASE("docs/validation.md is what the case records and READMEs generate, byte for byte") {
  const fs::path source(VALSALVA_SOURCE_DIR);
  const auto generated = generate(source / "validation", registered_case_docs());
  const fs::path committed = source / "docs/validation.md";
  if (read_text(committed) != generated) {
    const fs::path fresh = fs::current_path() / "validation.md.generated";
    write_text(fresh, generated);
    FAIL_CHECK(committed.string()
               << " is out of date with validation/README.md, validation/<case>/README.md, "
                  "validation/<case>/results/*.json or validation/notes/*.md; regenerate it "
                  "with\n  build/bin/valsalva docs-validation > docs/validation.md\nor copy "
               << fresh.string());
  }
  // Every registered case has its row and its section.
  for (const auto& c : all_cases()) {
    CAPTURE(c.name);
    CHECK(contains(generated, "| [" + c.name + "](#" + c.name + ") |"));
    CHECK(contains(generated, "\n## " + c.name + "\n"));
  }
}

TEST_CASE("a measured record gives its metrics table and a summary row naming the worst metric") {
  ScratchDir dir;
  Report r;
  r.add("error of a", 0.004, 0, 0.01, Check::at_most);         // room 0.6
  r.add("order of b", 1.85, 1.8, 0, Check::at_least);          // room 0.028: the closest
  r.add("drag of \"c\"\n", 5.58, 5.579, 0.01, Check::within);  // room 0.9, name escaped
  const RecordOrigin origin{"valsalva validate alpha", "2026-12-04T10:00:00Z", "0123456789abcdef",
                            "host: 2 cores"};
  write_record(record_file(dir.path / "alpha", Level::full),
               measured_record("alpha", Level::full, report_of(r), origin));
  write_text(dir.path / "alpha/README.md",
             "# alpha\n\nWhat: checks a.\n\n<!-- results -->\n\n## Open gap\n\nb is close.\n");
  const auto md = generate(dir.path, {{"alpha", "the alpha case"}});
  CHECK(contains(md,
                 "| [alpha](#alpha) | order of b | 1.85 | >= 1.8 | pass (3 of 3) | full | "
                 "2026-12-04 |"));
  CHECK(contains(md, "| error of a | 0.004 | <= 0.01 | pass |"));
  CHECK(contains(md, "| drag of \"c\"  | 5.58 | 5.579 +- 0.01 | pass |"));
  CHECK(contains(md, "commit 0123456789ab"));
  // The README's text, the results at its marker, its heading one level down.
  const auto what = md.find("What: checks a.");
  const auto results = md.find("### Results");
  const auto gap = md.find("### Open gap");
  CHECK(what < results);
  CHECK(results < gap);
  CHECK(gap != std::string::npos);
  CHECK(contains(md, "**Quick level**: not measured"));

  // A failing metric is the one shown, and the record says FAIL.
  r.add("leak", 0.2, 0, 0.1, Check::at_most);
  write_record(record_file(dir.path / "alpha", Level::quick),
               measured_record("alpha", Level::quick, report_of(r), origin));
  const auto failing = generate(dir.path, {{"alpha", ""}});
  CHECK(
      contains(failing, "| [alpha](#alpha) | leak | 0.2 | <= 0.1 | FAIL (3 of 4 pass) | quick |"));
}

TEST_CASE("a case without records or README is listed as not measured, not an error") {
  ScratchDir dir;
  const auto md = generate(dir.path, {{"zeta", "a new case"}, {"beta", "another"}});
  CHECK(contains(md, "| [beta](#beta) | not measured | - | - | no record | - | - |"));
  CHECK(contains(md, "| [zeta](#zeta) | not measured |"));
  CHECK(md.find("## beta") < md.find("## zeta"));  // name order
  CHECK(contains(md, "No README.md in validation/zeta/ yet."));
  CHECK(contains(md, "`valsalva validate zeta --quick --record` makes one"));
}

TEST_CASE("a carried-over record prints its documented tables and its source") {
  ScratchDir dir;
  const auto record = json::parse(R"({
    "case": "gamma", "level": "full", "origin": "carried_over",
    "command": "build/bin/valsalva validate gamma", "date": "2026-12-02", "commit": "1978fda",
    "machine": "not recorded", "source": "docs/validation.md lines 10-14 at commit 1978fda",
    "pass": false,
    "summary": {"metric": "c_D max", "measured": "3.2140", "target": "3.22-3.24",
                "result": "does not meet"},
    "tables": [{"columns": ["check", "measured"], "rows": [["max |p - p_exact|", "1.2e-9"]]}]
  })");
  write_record(record_file(dir.path / "gamma", Level::full), record);
  const auto md = generate(dir.path, {{"gamma", ""}});
  CHECK(contains(md,
                 "| [gamma](#gamma) | c_D max | 3.2140 | 3.22-3.24 | does not meet | full | "
                 "2026-12-02 (carried over) |"));
  CHECK(contains(md, "| max \\|p - p_exact\\| | 1.2e-9 |"));
  CHECK(contains(md, "docs/validation.md lines 10-14 at commit 1978fda"));
  CHECK(contains(md, "Not met when measured"));
}

TEST_CASE("records that do not parse or lack a field are errors naming the file") {
  ScratchDir dir;
  const auto file = record_file(dir.path / "delta", Level::quick);
  write_text(file, "{\"case\": \"delta\",");
  CHECK_THROWS_WITH_AS(read_record(file), doctest::Contains("quick.json"), std::runtime_error);
  write_text(file, R"({"case": "delta", "level": "quick", "origin": "measured"})");
  CHECK_THROWS_WITH_AS(read_record(file), doctest::Contains("\"command\""), std::runtime_error);
  CHECK_FALSE(read_record(dir.path / "nowhere.json").has_value());
}

TEST_CASE("report.json escapes control characters and writes null for values that are not finite") {
  ScratchDir dir;
  Report r;
  r.add("tab\there \x01", std::nan(""), 0, 1, Check::at_most);
  r.write_json(dir.path / "report.json", "eps\"ilon", 1, 0.5);
  const auto text = read_text(dir.path / "report.json");
  CHECK(contains(text, "\\t"));
  CHECK(contains(text, "\\u0001"));
  const auto parsed = json::parse(text);
  CHECK(parsed.at("case") == "eps\"ilon");
  CHECK(parsed.at("metrics").at(0).at("name") == "tab\there \x01");
  CHECK(parsed.at("metrics").at(0).at("value").is_null());
  CHECK(parsed.at("pass") == false);
}
