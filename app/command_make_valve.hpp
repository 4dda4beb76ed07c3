// `valsalva make-valve OUT_DIR [--set key=value ...] [--overwrite] [--leaflets-only]`: the
// parametric valve's files (valve/make_valve.hpp, docs/valve.md).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace valsalva::app {

// Registers the subcommand on `cli`; `action` is set to the function main() calls when the
// subcommand was given (after parsing, inside main's error handling).
CLI::App* add_make_valve(CLI::App& cli, std::function<int()>& action);

}  // namespace valsalva::app
