// The validation contract: a case computes metrics against an external reference, writes
// DIR/report.json and PNG plots, and fails when a metric is outside its tolerance.
// Cases live in validation/<case>/ and are listed once in validation/registry.cpp.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace valsalva::validation {

// How `value` is judged against `reference`:
//   within   |value - reference| <= tolerance
//   at_most  value <= reference + tolerance   (error norms, costs)
//   at_least value >= reference - tolerance   (observed orders)
enum class Check { within, at_most, at_least };

struct Metric {
  std::string name;
  double value = 0;
  double reference = 0;
  double tolerance = 0;
  Check check = Check::within;
  bool pass() const;
};

struct Context {
  MPI_Comm comm = MPI_COMM_WORLD;
  bool quick = false;
  std::filesystem::path out_dir;  // created before the case runs
  std::filesystem::path
      case_dir;  // validation/<case>/ in the source tree (reference data, plot.py)
  std::filesystem::path refdata_dir;  // validation/refdata (copies of ../shared/refdata)
  // Case options from `valsalva validate CASE --set key=value` (keys checked against
  // Case::options before the case runs); the accessors check the values.
  std::map<std::string, std::string> options;

  // The value of `key` (already checked against its CaseOption), or `fallback` when not set.
  std::string option(const std::string& key, const std::string& fallback = "") const;
  double option_real(const std::string& key, double fallback) const;
  int option_int(const std::string& key, int fallback) const;
};

class Report {
 public:
  void add(Metric m) { metrics_.push_back(std::move(m)); }
  void add(const std::string& name, double value, double reference, double tolerance,
           Check check = Check::within) {
    metrics_.push_back({name, value, reference, tolerance, check});
  }
  const std::vector<Metric>& metrics() const { return metrics_; }
  bool all_pass() const;
  // {"case","ranks","wall_seconds","pass","metrics":[{"name","value","reference","tolerance",
  // "check","pass"}]}; a value that is not finite is null.
  nlohmann::ordered_json to_json(const std::string& case_name, int ranks,
                                 double wall_seconds) const;
  void write_json(const std::filesystem::path& file, const std::string& case_name, int ranks,
                  double wall_seconds) const;

 private:
  std::vector<Metric> metrics_;
};

// An option a case accepts (`--set key=value`): for runs beyond the default one (a single
// level, a longer run, a timing run), so that the default stays within the CPU budget. The
// value is checked when the command line is read, before the case runs.
struct CaseOption {
  enum class Kind { real, integer, choice, directory };
  std::string key;
  std::string help;  // what it does and the default
  Kind kind = Kind::choice;
  double lo = 0, hi = 0;             // real, integer: the accepted range
  std::vector<std::string> choices;  // choice: the accepted words

  static CaseOption real(std::string key, std::string help, double lo, double hi);
  static CaseOption integer(std::string key, std::string help, int lo, int hi);
  static CaseOption choice(std::string key, std::string help, std::vector<std::string> words);
  static CaseOption directory(std::string key, std::string help);  // an existing folder
  // What the value must be ("a number in [0, 100]", "one of fsi1, fsi3").
  std::string accepted() const;
};

struct Case {
  std::string name;
  std::string description;
  std::function<void(const Context&, Report&)> run;
  std::vector<CaseOption> options = {};
};

// The options map of `case_def` from "key=value" strings; std::invalid_argument for a string
// without '=', an empty or repeated key, a key the case does not accept (naming the case and
// listing its keys) or a value outside what the option accepts.
std::map<std::string, std::string> parse_case_options(const Case& case_def,
                                                      const std::vector<std::string>& settings);

const std::vector<Case>& all_cases();
const Case* find_case(const std::string& name);

// Runs Debian's `/usr/bin/python3 <case_dir>/plot.py <out_dir>` on rank 0 when the case ships a
// plot script; returns false (with a message on stderr) when the plot could not be made.
bool run_plot_script(const Context& ctx);

}  // namespace valsalva::validation
