// `valsalva export-piv`: a run's phase statistics sampled on a PIV grid, written as a PIV file.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace valsalva::app {

// Registers the subcommand on `cli`; `action` is set to the function main() calls when the
// subcommand was given (after parsing, inside main's error handling).
CLI::App* add_export_piv(CLI::App& cli, std::function<int()>& action);

}  // namespace valsalva::app
