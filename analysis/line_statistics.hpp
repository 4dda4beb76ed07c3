// Phase- or time-averaged statistics at points along a line segment
// (analysis/phase_accumulator.hpp), for scenes that need profiles rather than fields: a diameter
// across a pipe, the axis of a jet. The values at the points come from analysis::Probes (point
// location in the replicated mesh, interpolation with the containing cell's shape functions, the
// same bits at any rank count), so every rank holds the same accumulators; rank 0 saves them in
// checkpoints and writes <dir>/<name>.csv with one row per (phase bin, point):
//   bin, phase_time, s (arc length from the origin, m), x, y, z, samples,
//   mean_u, mean_v, mean_w, mean_p, rms_u, rms_v, rms_w, rms_p, uu, vv, ww, uv, vw, uw, k
// Points outside the mesh are left out, as with line samples (a diameter whose ends lie on the
// curved wall loses the ends that the polygonal mesh wall does not contain); outside() counts
// them, and a line with no point inside is an error.
//
// How analysis::RunAnalysis uses it (all collective):
//   analysis::LineStatistics line(mesh, metrics, local, phase_options, {origin, end, points}, key);
//   after each step (every_steps): line.add(state);
//   checkpoint: line.checkpoint_arrays(); restart: line.restore(reader);
//   output: line.write(run_dir / "statistics");
#pragma once

#include <Eigen/Dense>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "analysis/phase_accumulator.hpp"
#include "analysis/probes.hpp"

namespace valsalva::analysis {

// points >= 2 points from origin to end (both included), evenly spaced.
struct LineSpec {
  Eigen::Vector3d origin{0, 0, 0}, end{0, 0, 0};  // m
  int points = 2;
};

class LineStatistics : public PhaseAccumulator {
 public:
  // Collective. `key` names the scene table in errors (e.g. "statistics.axis"). Throws
  // std::invalid_argument for a degenerate line or fewer than 2 points, std::runtime_error when
  // no point is inside the mesh.
  LineStatistics(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                 const mesh::LocalMesh& local, PhaseStatisticsOptions options, LineSpec line,
                 const std::string& key);

  const LineSpec& line() const { return line_; }
  // Points kept (inside the mesh), their arc length from the origin and how many were left out.
  const std::vector<ProbePoint>& points() const { return probes_->points(); }
  const std::vector<double>& arc_length() const { return arc_; }
  int outside() const { return line_.points - static_cast<int>(arc_.size()); }

  // Collective: interpolates u, v, w, p at the points and adds them (ignored before start).
  void add(const flow::FlowState& state);

  // <name>_moments, _counts, _meta (analysis/phase_accumulator.hpp) and <name>_points (x, y, z),
  // saved by rank 0: the accumulators are the same on every rank.
  std::vector<io::CheckpointArray> checkpoint_arrays() const;
  // Collective. Throws naming the checkpoint when the options or the points differ.
  void restore(const io::CheckpointReader& reader);
  // Collective (rank 0 writes): <dir>/<name>.csv. Returns its path.
  std::filesystem::path write(const std::filesystem::path& dir) const;

 private:
  struct Inside {
    std::vector<ProbePoint> points;
    std::vector<double> arc;
  };
  LineStatistics(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                 const mesh::LocalMesh& local, PhaseStatisticsOptions options, LineSpec line,
                 Inside inside);
  static Inside inside_points(const mesh::Mesh& mesh, const LineSpec& line, const std::string& key);

  LineSpec line_;
  std::vector<double> arc_;
  std::unique_ptr<Probes> probes_;
  std::vector<std::int64_t> rows_;  // 0 .. points - 1
};

}  // namespace valsalva::analysis
