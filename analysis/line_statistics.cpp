#include "analysis/line_statistics.hpp"

#include <fmt/format.h>

#include <fstream>
#include <numeric>
#include <stdexcept>

#include "mesh/point_locator.hpp"

namespace valsalva::analysis {

LineStatistics::Inside LineStatistics::inside_points(const mesh::Mesh& mesh, const LineSpec& line,
                                                     const std::string& key) {
  const Eigen::Vector3d d = line.end - line.origin;
  if (!(d.norm() > 0))
    throw std::invalid_argument(fmt::format("{}.end: the line has zero length", key));
  if (line.points < 2)
    throw std::invalid_argument(
        fmt::format("{}.points: {} point(s) do not make a line (at least 2)", key, line.points));
  const mesh::PointLocator locator(mesh);
  Inside in;
  for (int i = 0; i < line.points; ++i) {
    const double t = double(i) / (line.points - 1);
    const Eigen::Vector3d x = line.origin + t * d;
    if (!locator.locate(x)) continue;
    in.points.push_back({fmt::format("{}_{}", key, i), x});
    in.arc.push_back(t * d.norm());
  }
  if (in.points.empty())
    throw std::runtime_error(
        fmt::format("{}: none of the {} points from ({}, {}, {}) to ({}, {}, {}) m is inside the "
                    "mesh '{}'",
                    key, line.points, line.origin.x(), line.origin.y(), line.origin.z(),
                    line.end.x(), line.end.y(), line.end.z(), mesh.source));
  return in;
}

LineStatistics::LineStatistics(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                               const mesh::LocalMesh& local, PhaseStatisticsOptions options,
                               LineSpec line, const std::string& key)
    : LineStatistics(mesh, metrics, local, std::move(options), line,
                     inside_points(mesh, line, key)) {}

LineStatistics::LineStatistics(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                               const mesh::LocalMesh& local, PhaseStatisticsOptions options,
                               LineSpec line, Inside inside)
    : PhaseAccumulator(std::move(options), inside.points.size()),
      line_(line),
      arc_(std::move(inside.arc)),
      probes_(std::make_unique<Probes>(mesh, metrics, local, std::move(inside.points))),
      rows_(arc_.size()) {
  std::iota(rows_.begin(), rows_.end(), 0);
}

void LineStatistics::add(const flow::FlowState& state) {
  if (state.time < options_.start_time) return;
  add_sample(bin_of(state.time), cycle_of(state.time), probes_->sample(state));
}

std::vector<io::CheckpointArray> LineStatistics::checkpoint_arrays() const {
  const bool root = probes_->comm().root();
  const std::span<const std::int64_t> rows =
      root ? std::span<const std::int64_t>(rows_) : std::span<const std::int64_t>();
  const auto n = static_cast<std::int64_t>(rows_.size());
  auto arrays = moment_arrays(rows, n, root);
  io::CheckpointArray positions{options_.name + "_points", n, 3, {rows.begin(), rows.end()}, {}};
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int c = 0; c < 3; ++c) positions.data.push_back(points()[i].position[c]);
  arrays.push_back(std::move(positions));
  return arrays;
}

void LineStatistics::restore(const io::CheckpointReader& reader) {
  const std::string where =
      fmt::format("checkpoint '{}', statistics '{}'", reader.path().string(), options_.name);
  restore_moments(reader, rows_, static_cast<std::int64_t>(rows_.size()), where);
  // The points follow from the scene's numbers by the same arithmetic: equal bits, or another
  // line (or a mesh that now contains other points of it).
  const auto saved = reader.read_array(options_.name + "_points", rows_);
  for (std::size_t i = 0; i < rows_.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (saved[3 * i + c] != points()[i].position[c])
        throw std::runtime_error(fmt::format(
            "{}: saved point {} is at ({}, {}, {}) m, this run's at ({}, {}, {}) m", where, i,
            saved[3 * i], saved[3 * i + 1], saved[3 * i + 2], points()[i].position.x(),
            points()[i].position.y(), points()[i].position.z()));
}

std::filesystem::path LineStatistics::write(const std::filesystem::path& dir) const {
  const auto path = dir / (options_.name + ".csv");
  if (!probes_->comm().root()) return path;
  std::filesystem::create_directories(dir);
  std::ofstream csv(path);
  csv << "bin,phase_time,s,x,y,z,samples,mean_u,mean_v,mean_w,mean_p,rms_u,rms_v,rms_w,rms_p,"
         "uu,vv,ww,uv,vw,uw,k\n";
  for (int b = 0; b < options_.bins; ++b)
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      const int p = int(i);
      const auto& x = points()[i].position;
      csv << fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{}", b, phase_time(b), arc_[i],
                         x.x(), x.y(), x.z(), count(b));
      for (int q = 0; q < 4; ++q) csv << fmt::format(",{:.17g}", mean(b, p, q));
      for (int q = 0; q < 4; ++q) csv << fmt::format(",{:.17g}", rms(b, p, q));
      csv << fmt::format(
          ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", reynolds_stress(b, p, 0, 0),
          reynolds_stress(b, p, 1, 1), reynolds_stress(b, p, 2, 2), reynolds_stress(b, p, 0, 1),
          reynolds_stress(b, p, 1, 2), reynolds_stress(b, p, 0, 2), kinetic_energy(b, p));
    }
  if (!csv) throw std::runtime_error(fmt::format("statistics: cannot write '{}'", path.string()));
  return path;
}

}  // namespace valsalva::analysis
