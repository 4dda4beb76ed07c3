// The validation contract: a case computes metrics against an external reference, writes
// DIR/report.json and PNG plots, and fails when a metric is outside its tolerance.
// Cases live in validation/<case>/ and are listed once in validation/registry.cpp.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <functional>
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
  // {"case","ranks","wall_seconds","metrics":[{"name","value","reference","tolerance","pass"}]}
  void write_json(const std::filesystem::path& file, const std::string& case_name, int ranks,
                  double wall_seconds) const;

 private:
  std::vector<Metric> metrics_;
};

struct Case {
  std::string name;
  std::string description;
  std::function<void(const Context&, Report&)> run;
};

const std::vector<Case>& all_cases();
const Case* find_case(const std::string& name);

// Runs Debian's `/usr/bin/python3 <case_dir>/plot.py <out_dir>` on rank 0 when the case ships a
// plot script; returns false (with a message on stderr) when the plot could not be made.
bool run_plot_script(const Context& ctx);

}  // namespace valsalva::validation
