// The simulation's phase statistics as a PIV file: a regular grid of vectors in the PIV plane
// (the experiment's own layout: nx x ny vectors `spacing` apart), the in-plane mean velocity and
// RMS of each phase bin sampled on it exactly as `valsalva compare-piv` samples them
// (analysis::PivSampler), written in the CSV that analysis::read_piv_csv reads. So a run's plane
// statistics can be handed to PIV tools, compared with another run's, and read back by
// compare-piv without loss (the round trip of the valve issue, tests/app/piv_round_trip_test.sh).
#pragma once

#include <filesystem>
#include <string>

#include "analysis/piv_compare.hpp"
#include "analysis/piv_data.hpp"

namespace valsalva::analysis {

struct PivGrid {
  int nx = 63, ny = 79;      // vectors along the PIV x and y axes (the valve case's PIV)
  double spacing = 0.68e-3;  // m between neighbouring vectors
  double x0 = 0, y0 = 0;     // PIV-plane coordinates of the first vector, m
};

// The grid's points, x fastest, all valid (no velocities yet). Throws std::invalid_argument
// naming the field when nx or ny < 1, or spacing, x0, y0 are not finite (spacing > 0).
PivFrame piv_grid_frame(const PivGrid& grid);

// Fills the frame's u, v (and u_rms, v_rms when the statistics have RMS) from the statistics at
// its points; a point outside the mesh or outside the covered nodes (NaN statistics) is masked.
void sample_statistics(const PivSampler& sampler, const SimulationStatistics& sim, PivFrame& frame);

// Writes `data` as PIV CSV (read_piv_csv): '#' lines of `comment`, then x, y, u, v [, u_rms,
// v_rms], valid [, phase | time] with 17 significant digits (read back bit for bit); a masked
// velocity is an empty field. Throws std::runtime_error naming the path when it cannot write.
void write_piv_csv(const std::filesystem::path& path, const PivData& data,
                   const std::string& comment);

}  // namespace valsalva::analysis
