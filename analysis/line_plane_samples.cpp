#include "analysis/line_plane_samples.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "mesh/point_locator.hpp"

namespace valsalva::analysis {

LinePlaneSamples::LinePlaneSamples(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                                   const mesh::LocalMesh& local, SampleOptions options)
    : options_(std::move(options)), next_(options_.start_time) {
  const mesh::PointLocator locator(mesh);
  const auto [ni, nj] = options_.points;
  std::vector<ProbePoint> inside;
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i) {
      const double s = ni > 1 ? double(i) / (ni - 1) : 0.0;
      const double t = nj > 1 ? double(j) / (nj - 1) : 0.0;
      const Eigen::Vector3d x = options_.origin + s * options_.u + t * options_.v;
      if (!locator.locate(x)) continue;
      inside.push_back({fmt::format("{}_{}_{}", options_.name, i, j), x});
      index_.push_back({i, j});
    }
  if (inside.empty())
    throw std::runtime_error(
        fmt::format("sample '{}': none of its {} points is inside the mesh '{}'", options_.name,
                    ni * nj, mesh.source));
  probes_ = std::make_unique<Probes>(mesh, metrics, local, std::move(inside));
}

bool LinePlaneSamples::due(double time) {
  const double eps = 1e-12 * std::max(1.0, std::abs(time));
  if (time < next_ - eps) return false;
  if (options_.interval > 0)
    while (next_ <= time + eps) next_ += options_.interval;
  return true;
}

void LinePlaneSamples::write(const flow::FlowState& state, std::int64_t step,
                             const std::filesystem::path& dir) {
  const auto values = probes_->sample(state);  // collective
  if (!probes_->comm().root()) return;
  const auto path = dir / fmt::format("{}_{:09d}.csv", options_.name, step);
  std::ofstream out(path);
  if (!out) throw std::runtime_error("sample: cannot write " + path.string());
  out << "time,i,j,x,y,z,u,v,w,p\n";
  const auto& pts = probes_->points();
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const auto& x = pts[k].position;
    out << fmt::format("{:.17g},{},{},{:.9e},{:.9e},{:.9e},{:.17g},{:.17g},{:.17g},{:.17g}\n",
                       state.time, index_[k][0], index_[k][1], x.x(), x.y(), x.z(), values[4 * k],
                       values[4 * k + 1], values[4 * k + 2], values[4 * k + 3]);
  }
}

}  // namespace valsalva::analysis
