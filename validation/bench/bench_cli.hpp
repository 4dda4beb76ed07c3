// Command lines of the benchmark executables, through CLI11 as in app/main.cpp: every option
// typed, checked and listed with its default by --help; an unknown option or a bad value is
// refused on stderr with exit code 2 (--help: exit code 0). Under MPI every rank parses, rank 0
// alone prints, and every rank finalises MPI and exits with the same code.
#pragma once

#include <fmt/format.h>
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <utility>

namespace valsalva::bench {

// A CLI11 application named `name` (the executable) whose --help shows each option's default.
class App : public CLI::App {
 public:
  App(std::string name, std::string description)
      : CLI::App(std::move(description), std::move(name)) {
    option_defaults()->always_capture_default();
  }
};

// Checks for numeric options (also of vectors, element by element), with shorter messages than
// CLI::PositiveNumber's; "inf" is a number (bench_taylor_green_study --re inf).
inline CLI::Validator at_least(double bound, bool strict, const std::string& name) {
  return CLI::Validator(
      [=](std::string& value) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(value, x)) return "'" + value + "' is not a number";
        if (strict ? x > bound : x >= bound) return {};
        return fmt::format("{} is not {} {:g}", value, strict ? ">" : ">=", bound);
      },
      name);
}
inline const CLI::Validator positive = at_least(0, true, "POSITIVE");
inline const CLI::Validator non_negative = at_least(0, false, "NONNEGATIVE");

// Parses the command line. nullopt: go on; else the exit code for main (0 after --help, 2 for a
// bad command line), with the help text or the error printed where `print`.
inline std::optional<int> parse(CLI::App& app, int argc, char** argv, bool print = true) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    if (print) app.exit(e);
    return e.get_exit_code() == 0 ? 0 : 2;
  }
}

// The main() of an MPI benchmark: MPI_Init, parse (as above, printing on rank 0), then
// run(rank, size). An exception from run: "<name>: <what>" on stderr from rank 0 and exit code 1
// (MPI_Abort at more than one rank, so that no rank is left waiting in a collective).
inline int mpi_main(CLI::App& app, int argc, char** argv,
                    const std::function<void(int rank, int size)>& run) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1, status = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (const auto code = parse(app, argc, argv, rank == 0)) {
    status = *code;
  } else {
    try {
      run(rank, size);
    } catch (const std::exception& e) {
      if (rank == 0) fmt::print(stderr, "{}: {}\n", app.get_name(), e.what());
      if (size > 1) MPI_Abort(MPI_COMM_WORLD, 1);
      status = 1;
    }
  }
  MPI_Finalize();
  return status;
}

}  // namespace valsalva::bench
