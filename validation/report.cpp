#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <cstdlib>

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
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  return fmt::format("{:.17g}", x);
}
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}
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
}  // namespace

void Report::write_json(const std::filesystem::path& file, const std::string& case_name, int ranks,
                        double wall_seconds) const {
  auto out = fmt::output_file(file.string());
  out.print("{{\n  \"case\": {},\n  \"ranks\": {},\n  \"wall_seconds\": {},\n  \"pass\": {},\n",
            json_string(case_name), ranks, json_number(wall_seconds),
            all_pass() ? "true" : "false");
  out.print("  \"metrics\": [\n");
  for (std::size_t i = 0; i < metrics_.size(); ++i) {
    const auto& m = metrics_[i];
    out.print(
        "    {{\"name\": {}, \"value\": {}, \"reference\": {}, \"tolerance\": {}, \"check\": "
        "\"{}\", \"pass\": {}}}{}\n",
        json_string(m.name), json_number(m.value), json_number(m.reference),
        json_number(m.tolerance), check_name(m.check), m.pass() ? "true" : "false",
        i + 1 < metrics_.size() ? "," : "");
  }
  out.print("  ]\n}}\n");
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
  MPI_Bcast(&ok, 1, MPI_INT, 0, ctx.comm);
  return ok == 1;
}

}  // namespace valsalva::validation
