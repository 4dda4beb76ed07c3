#include "io/solid_series.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

namespace valsalva::io {

SolidSeries::SolidSeries(std::filesystem::path dir, std::string basename,
                         const structure::SolidMesh& mesh)
    : dir_(std::move(dir)), basename_(std::move(basename)), mesh_(&mesh) {
  std::filesystem::create_directories(dir_);
}

std::filesystem::path SolidSeries::write(double time, const Eigen::Matrix3Xd& x,
                                         const structure::NodalStress* stress,
                                         const SolidVectors& vectors) {
  const std::string step = fmt::format("{}_{:06d}", basename_, grids_.size());
  const std::string body = write_solid_h5(dir_, step, *mesh_, x, stress, vectors);
  grids_.push_back(
      fmt::format("    <Grid Name=\"{}\" GridType=\"Uniform\">\n      <Time "
                  "Value=\"{:.17g}\"/>\n{}    </Grid>\n",
                  step, time, body));
  // Written to a temporary name and renamed: a reader never sees half a file.
  const auto xmf = xmf_file();
  const auto tmp = dir_ / (basename_ + ".xmf.tmp");
  {
    std::ofstream out(tmp);
    out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
        << fmt::format("  <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                       basename_);
    for (const auto& g : grids_) out << g;
    out << "  </Grid>\n  </Domain>\n</Xdmf>\n";
    if (!out) throw std::runtime_error(fmt::format("solid output: cannot write {}", tmp.string()));
  }
  std::filesystem::rename(tmp, xmf);
  return dir_ / (step + ".h5");
}

}  // namespace valsalva::io
