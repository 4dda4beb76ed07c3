// `valsalva close-leaflets LEAFLETS.msh --out CLOSED.msh [--pressure P] ...`: the closing
// preprocessing (valve/leaflet_closing.hpp). Writes the closed leaflets as a Gmsh hex mesh with
// the same physical groups (the FSI scene's stress-free reference) and CLOSED.closing.toml with
// the report (pressure steps, Newton iterations, free-edge midpoints, coaptation height, orifice
// area, largest von Mises stress and where). Runs on rank 0.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace valsalva::app {

CLI::App* add_close_leaflets(CLI::App& cli, std::function<int()>& action);

}  // namespace valsalva::app
