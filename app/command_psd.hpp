// `valsalva psd`: power spectral density of probe time series (Welch), from the command line.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace valsalva::app {

// Registers the subcommand on `cli`; `action` is set to the function main() calls when the
// subcommand was given (after parsing, inside main's error handling).
CLI::App* add_psd(CLI::App& cli, std::function<int()>& action);

}  // namespace valsalva::app
