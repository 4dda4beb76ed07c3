// Probes: user points located once in the replicated mesh (mesh::PointLocator), nodal values
// interpolated with the containing cell's shape functions. The values a probe needs are gathered
// from their owners by a sum in which every entry has exactly one non-zero contribution, and the
// interpolation then runs in a fixed order on every rank, so the samples have the same bits at
// any rank count.
//
// How the run loop uses it (all collective):
//   analysis::Probes probes(mesh, metrics, local, scene_probe_points);   // throws if a point is
//   outside analysis::ProbeCsv csv(run_dir / "probes.csv", probes);              // header written
//   by rank 0 every N steps: csv.append(state.time, probes.sample(state));    // u, v, w, p per
//   probe
#pragma once

#include <Eigen/Dense>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/comm.hpp"
#include "flow/projection_rk4.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/point_locator.hpp"

namespace valsalva::analysis {

struct ProbePoint {
  std::string name;
  Eigen::Vector3d position{0, 0, 0};  // m
};

class Probes {
 public:
  // Throws std::runtime_error "probe '<name>' at (x, y, z) m is outside the mesh '<source>'".
  Probes(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics, const mesh::LocalMesh& local,
         std::vector<ProbePoint> points);

  const std::vector<ProbePoint>& points() const { return points_; }
  const std::vector<mesh::PointLocation>& locations() const { return locations_; }
  const core::Comm& comm() const { return local_->comm; }

  // Collective. `values` holds `components` doubles per local node (node-major, owned first);
  // returns points().size() x components values (row-major), identical on every rank.
  std::vector<double> sample(std::span<const double> values, int components) const;
  // Collective. u, v, w, p per probe.
  std::vector<double> sample(const flow::FlowState& state) const;

 private:
  // Sums buffer_ (the needed nodes' values, zero where not owned) over ranks and interpolates.
  std::vector<double> gather_and_interpolate(int components) const;

  const mesh::LocalMesh* local_;
  std::vector<ProbePoint> points_;
  std::vector<mesh::PointLocation> locations_;
  std::vector<mesh::GlobalIndex> needed_;  // dual nodes the probes need (sorted, unique)
  std::vector<int> needed_local_;          // local owned index, or -1
  std::vector<std::vector<int>> slot_;     // per probe and cell node: index into needed_
  mutable std::vector<double> buffer_, gathered_;
};

// Probe time series as CSV: "time,<name>_u,<name>_v,<name>_w,<name>_p,..." (17 significant
// digits, one row per sample). Only rank 0 touches the file.
class ProbeCsv {
 public:
  ProbeCsv(const std::filesystem::path& path, const Probes& probes,
           std::vector<std::string> components = {"u", "v", "w", "p"}, bool append = false);
  void append(double time, const std::vector<double>& values);

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::size_t width_ = 0;
};

// Reads a ProbeCsv file back: column names and rows (for spectra and tests).
struct ProbeSeries {
  std::vector<std::string> columns;  // "time" first
  std::vector<std::vector<double>> rows;
  std::vector<double> column(const std::string& name) const;  // throws naming the file/column
  std::string source;
};
ProbeSeries read_probe_csv(const std::filesystem::path& path);

}  // namespace valsalva::analysis
