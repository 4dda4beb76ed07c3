#include "analysis/wall_shear_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace valsalva::analysis {

std::vector<WallShearSummary> summarize_wall_shear(const std::vector<WallNodeRow>& rows,
                                                   std::size_t patches) {
  std::vector<WallShearSummary> out(patches);
  std::vector<double> rrt_area(patches, 0.0), clear_area(patches, 0.0);
  for (const auto& r : rows) {
    auto& s = out.at(std::size_t(r.patch));
    s.area += r.area;
    s.mean_tawss += r.area * r.tawss;
    s.mean_osi += r.area * r.osi;
    s.max_tawss = std::max(s.max_tawss, r.tawss);
    s.max_osi = std::max(s.max_osi, r.osi);
    if (r.support == 0) {
      s.clear_mean_tawss += r.area * r.tawss;
      s.clear_max_tawss = std::max(s.clear_max_tawss, r.tawss);
      clear_area[std::size_t(r.patch)] += r.area;
    }
    if (std::isfinite(r.rrt)) {
      s.mean_rrt += r.area * r.rrt;
      rrt_area[std::size_t(r.patch)] += r.area;
    }
  }
  for (std::size_t p = 0; p < patches; ++p) {
    auto& s = out[p];
    if (s.area > 0) {
      s.mean_tawss /= s.area;
      s.mean_osi /= s.area;
      s.rrt_area_fraction = rrt_area[p] / s.area;
      s.clear_area_fraction = clear_area[p] / s.area;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.mean_rrt = rrt_area[p] > 0 ? s.mean_rrt / rrt_area[p] : nan;
    s.clear_mean_tawss = clear_area[p] > 0 ? s.clear_mean_tawss / clear_area[p] : nan;
    if (!(clear_area[p] > 0)) s.clear_max_tawss = nan;
  }
  return out;
}

void write_wall_shear_summary(const std::filesystem::path& path,
                              const std::vector<std::string>& patches,
                              const std::vector<WallShearSummary>& summaries, double window_start,
                              double window_end) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("wall_shear: cannot write " + path.string());
  out << "patch,area,window_start,window_end,mean_tawss,max_tawss,mean_osi,max_osi,mean_rrt,"
         "rrt_area_fraction,clear_area_fraction,clear_mean_tawss,clear_max_tawss\n";
  for (std::size_t p = 0; p < summaries.size(); ++p) {
    const auto& s = summaries[p];
    out << fmt::format(
        "{},{:.9e},{:.17g},{:.17g},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}"
        "\n",
        patches[p], s.area, window_start, window_end, s.mean_tawss, s.max_tawss, s.mean_osi,
        s.max_osi, s.mean_rrt, s.rrt_area_fraction, s.clear_area_fraction, s.clear_mean_tawss,
        s.clear_max_tawss);
  }
}

std::string wall_shear_summary_line(const std::string& patch, const WallShearSummary& s,
                                    double window_start, double window_end) {
  std::string clear;
  if (s.clear_area_fraction < 1)
    clear = fmt::format(
        "; outside the immersed kernel supports ({:.1f} % of the area) TAWSS mean "
        "{:.4g} max {:.4g} Pa",
        100 * s.clear_area_fraction, s.clear_mean_tawss, s.clear_max_tawss);
  return fmt::format(
      "wall_shear {}: area {:.4e} m2, TAWSS mean {:.4g} max {:.4g} Pa, OSI mean {:.4f} max "
      "{:.4f}, RRT mean {:.4g} 1/Pa (defined on {:.1f} % of the area){}, t = [{:.6g}, {:.6g}] s",
      patch, s.area, s.mean_tawss, s.max_tawss, s.mean_osi, s.max_osi, s.mean_rrt,
      100 * s.rrt_area_fraction, clear, window_start, window_end);
}

}  // namespace valsalva::analysis
