#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/comm.hpp"
#include "validation/case.hpp"

namespace valsalva::validation {

bool Metric::pass() const {
  if (!std::isfinite(value)) return false;
  switch (check) {
    case Check::within:
      return std::abs(value - reference) <= tolerance;
    case Check::at_most:
      return value <= reference + tolerance;
    case Check::at_least:
      return value >= reference - tolerance;
  }
  return false;
}

bool Report::all_pass() const {
  for (const auto& m : metrics_)
    if (!m.pass()) return false;
  return !metrics_.empty();
}

namespace {
const char* check_name(Check c) {
  switch (c) {
    case Check::within:
      return "within";
    case Check::at_most:
      return "at_most";
    case Check::at_least:
      return "at_least";
  }
  return "?";
}
// JSON has no NaN or infinity: a value that is not finite is written as null (it fails).
nlohmann::ordered_json json_number(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nullptr;
}
}  // namespace

nlohmann::ordered_json Report::to_json(const std::string& case_name, int ranks,
                                       double wall_seconds) const {
  auto metrics = nlohmann::ordered_json::array();
  for (const auto& m : metrics_)
    metrics.push_back({{"name", m.name},
                       {"value", json_number(m.value)},
                       {"reference", json_number(m.reference)},
                       {"tolerance", json_number(m.tolerance)},
                       {"check", check_name(m.check)},
                       {"pass", m.pass()}});
  return {{"case", case_name},
          {"ranks", ranks},
          {"wall_seconds", json_number(wall_seconds)},
          {"pass", all_pass()},
          {"metrics", metrics}};
}

void Report::write_json(const std::filesystem::path& file, const std::string& case_name, int ranks,
                        double wall_seconds) const {
  std::ofstream out(file);
  out << to_json(case_name, ranks, wall_seconds).dump(2) << "\n";
  if (!out) throw std::runtime_error("validate: could not write " + file.string());
}

bool run_plot_script(const Context& ctx) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  int ok = 1;
  const auto script = ctx.case_dir / "plot.py";
  if (rank == 0 && std::filesystem::exists(script)) {
    const std::string cmd =
        fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), ctx.out_dir.string());
    ok = std::system(cmd.c_str()) == 0 ? 1 : 0;
    if (!ok) fmt::print(stderr, "validate: plot script failed: {}\n", cmd);
  }
  core::Comm(ctx.comm).broadcast(ok);
  return ok == 1;
}

}  // namespace valsalva::validation
