#include "analysis/wall_shear_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace valsalva::analysis {

namespace {
constexpr std::size_t kWidth = 13;  // doubles per row on the wire
}

std::vector<WallNodeRow> gather_wall_rows(const core::Comm& comm,
                                          const std::vector<WallNodeRow>& mine) {
  std::vector<double> flat;
  flat.reserve(kWidth * mine.size());
  for (const auto& r : mine)
    flat.insert(flat.end(), {double(r.patch), double(r.node), r.x.x(), r.x.y(), r.x.z(), r.area,
                             r.tawss, r.osi, r.rrt, r.tau.x(), r.tau.y(), r.tau.z(), r.support});
  const auto all = comm.gather_to_root(flat);
  std::vector<WallNodeRow> rows(all.size() / kWidth);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double* v = &all[kWidth * i];
    rows[i] = {int(v[0]),
               std::int64_t(v[1]),
               {v[2], v[3], v[4]},
               v[5],
               v[6],
               v[7],
               v[8],
               {v[9], v[10], v[11]},
               v[12]};
  }
  std::sort(rows.begin(), rows.end(), [](const WallNodeRow& a, const WallNodeRow& b) {
    return std::pair(a.patch, a.node) < std::pair(b.patch, b.node);
  });
  return rows;
}

void write_wall_shear_csv(const std::filesystem::path& path,
                          const std::vector<std::string>& patches,
                          const std::vector<WallNodeRow>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("wall_shear: cannot write " + path.string());
  out << "patch,node,x,y,z,area,tawss,osi,rrt,tau_x,tau_y,tau_z,support_fraction\n";
  for (const auto& r : rows)
    out << fmt::format(
        "{},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}\n",
        patches[std::size_t(r.patch)], r.node, r.x.x(), r.x.y(), r.x.z(), r.area, r.tawss, r.osi,
        r.rrt, r.tau.x(), r.tau.y(), r.tau.z(), r.support);
}

}  // namespace valsalva::analysis
