// Instantaneous u, v, w, p on a line or a plane of points, written as one small CSV file per
// sample: samples/<name>_<step, 9 digits>.csv with columns time, i, j, x, y, z, u, v, w, p (j = 0
// on a line). Points outside the mesh are left out (a plane across a pipe covers a square); the
// values come from analysis::Probes, so they have the same bits at any rank count.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "analysis/analysis_options.hpp"
#include "analysis/probes.hpp"

namespace valsalva::analysis {

class LinePlaneSamples {
 public:
  // Collective. Throws std::runtime_error naming the sample when no point is inside the mesh.
  LinePlaneSamples(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                   const mesh::LocalMesh& local, SampleOptions options);

  const SampleOptions& options() const { return options_; }
  std::size_t points() const { return probes_->points().size(); }
  // True when a sample is due at this time (and advances the next sample time).
  bool due(double time);
  // Collective: writes <dir>/<name>_<step>.csv (rank 0).
  void write(const flow::FlowState& state, std::int64_t step, const std::filesystem::path& dir);

 private:
  SampleOptions options_;
  std::vector<std::array<int, 2>> index_;  // (i, j) of every point kept
  std::unique_ptr<Probes> probes_;
  double next_ = 0;
};

}  // namespace valsalva::analysis
