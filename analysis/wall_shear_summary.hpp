// Per-patch summary of the end-of-run wall shear statistics (wall_shear_summary.csv, one row per
// patch, and one log line each):
//   patch, area (m2: the sum of the wall nodes' dual-face areas), window_start, window_end (s:
//   the averaging window of TAWSS and OSI), mean_tawss, max_tawss (Pa), mean_osi, max_osi,
//   mean_rrt (1/Pa), rrt_area_fraction, clear_area_fraction, clear_mean_tawss, clear_max_tawss
//   (Pa: over the nodes never inside an immersed structure's kernel support in the window, the
//   share of the area they cover; nan means when none is)
// Means are area-weighted over the patch's wall nodes. RRT is undefined where the time-mean
// tau_w vector vanishes (flow::WallShearStatistics::rrt): mean_rrt is its area-weighted mean over
// the nodes where it is defined, rrt_area_fraction the share of the area they cover (nan mean
// when none is).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/wall_shear_rows.hpp"

namespace valsalva::analysis {

struct WallShearSummary {
  double area = 0, mean_tawss = 0, max_tawss = 0, mean_osi = 0, max_osi = 0, mean_rrt = 0,
         rrt_area_fraction = 0, clear_area_fraction = 0, clear_mean_tawss = 0, clear_max_tawss = 0;
};

// One summary per patch index in [0, patches), from the rows of every wall node.
std::vector<WallShearSummary> summarize_wall_shear(const std::vector<WallNodeRow>& rows,
                                                   std::size_t patches);

void write_wall_shear_summary(const std::filesystem::path& path,
                              const std::vector<std::string>& patches,
                              const std::vector<WallShearSummary>& summaries, double window_start,
                              double window_end);

// "wall_shear <patch>: area ..., TAWSS mean ... max ... Pa, OSI ..., RRT ... over [t0, t1] s".
std::string wall_shear_summary_line(const std::string& patch, const WallShearSummary& s,
                                    double window_start, double window_end);

}  // namespace valsalva::analysis
