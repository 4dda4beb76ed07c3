// The options that place a PIV plane in the simulation frame, shared by `compare-piv` and
// `export-piv`: --origin, --ex, --ey (three comma-separated numbers each, required).
#pragma once

#include <CLI/CLI.hpp>
#include <vector>

namespace valsalva::app {

struct PivPlaneOptions {
  std::vector<double> origin, ex, ey;
};

inline void add_piv_plane_options(CLI::App* command, PivPlaneOptions& plane) {
  const std::pair<const char*, std::vector<double>*> options[] = {
      {"--origin", &plane.origin}, {"--ex", &plane.ex}, {"--ey", &plane.ey}};
  const char* const help[] = {"PIV origin in the simulation frame, m (x,y,z)",
                              "PIV x axis in the simulation frame, unit vector",
                              "PIV y axis in the simulation frame, unit vector"};
  for (int i = 0; i < 3; ++i)
    command->add_option(options[i].first, *options[i].second, help[i])
        ->required()
        ->expected(3)
        ->delimiter(',');
}

}  // namespace valsalva::app
