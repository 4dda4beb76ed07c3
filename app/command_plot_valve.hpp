// `valsalva plot-valve`: PNG plots of a run's valve.csv and valve_cycles.csv
// (analysis/plot_valve.py).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace valsalva::app {

// Registers the subcommand on `cli`; `action` is set to the function main() calls when the
// subcommand was given (after parsing, inside main's error handling).
CLI::App* add_plot_valve(CLI::App& cli, std::function<int()>& action);

}  // namespace valsalva::app
