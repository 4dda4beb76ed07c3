// Phase-averaged statistics over cardiac cycles at mesh nodes, accumulated on the fly
// (analysis/phase_accumulator.hpp: Welford updates, Chan merges, the bins and the results).
// Memory: 11 doubles = 88 bytes per node and bin (a 1 M-node mesh, 20 bins: 1.76 GB over all
// ranks) plus 44 bytes per covered node; checkpoint_arrays() copies the moments once more while
// a checkpoint is written. Restrict `nodes` to planes or regions to save it (docs/analysis.md).
//
// How the run loop uses it:
//   analysis::PhaseStatistics stats(local, {period, bins, t_start, rho, "stats"},
//                                   nodes_near_plane(local, p0, n, 0.5e-3));  // or all_owned_nodes
//   after each step (t >= t_start):  stats.add(state.time, state.velocity, state.pressure);
//   checkpoint: writer.write(state, step, dt, stats.checkpoint_arrays());
//   restart:    stats.restore(reader);
//   output:     stats.write(mesh, metrics, run_dir / "statistics");   // collective
#pragma once

#include <Eigen/Dense>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/phase_accumulator.hpp"
#include "io/checkpoint.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::analysis {

class PhaseStatistics : public PhaseAccumulator {
 public:
  // `nodes`: owned local node indices covered (any order, unique). Throws naming bad options.
  PhaseStatistics(const mesh::LocalMesh& local, PhaseStatisticsOptions options,
                  std::vector<int> nodes);

  const std::vector<int>& nodes() const { return nodes_; }  // point i of the accumulator

  // Adds the sample of every covered node (local arrays, owned first). Ignored before start.
  void add(double time, const flow::VectorField& velocity, const flow::ScalarField& pressure);
  // Chan et al.'s pairwise merge of another accumulator over the same nodes and options.
  void merge(const PhaseStatistics& other);

  // Accumulators as checkpoint arrays <name>_moments, _counts, _meta, _nodes; rows of the
  // moments are the covered nodes numbered by increasing dual id over all ranks.
  std::vector<io::CheckpointArray> checkpoint_arrays() const;
  // Collective. Throws naming the checkpoint when options or covered nodes differ.
  void restore(const io::CheckpointReader& reader);

  // Collective. Writes <dir>/<name>.xmf + HDF5 (one XDMF step per bin at its phase time; fields
  // mean_velocity, mean_pressure, rms_velocity, rms_pressure, reynolds_uv, reynolds_uw,
  // reynolds_vw, k; NaN outside the covered nodes) and <dir>/<name>_phases.csv (bin,
  // phase_time, samples, cycles). Returns the .xmf path.
  std::filesystem::path write(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                              const std::filesystem::path& dir) const;

 private:
  const mesh::LocalMesh* local_;
  std::vector<int> nodes_;
  std::vector<std::int64_t> rows_;  // global subset row of every covered node
  std::int64_t global_rows_ = 0;
  std::vector<double> sample_;
};

// Covered-node selections (owned local indices).
std::vector<int> all_owned_nodes(const mesh::LocalMesh& local);
// Nodes within `half_thickness` of the plane through `point` with normal `normal`.
std::vector<int> nodes_near_plane(const mesh::LocalMesh& local, const Eigen::Vector3d& point,
                                  const Eigen::Vector3d& normal, double half_thickness);
// Owned nodes of the cells mesh::cells_cut_by_plane finds: every node that interpolation anywhere
// on the plane within the box needs (a slab of nodes near the plane misses some of them wherever
// cells are thicker than the slab, and the statistics there read as NaN).
std::vector<int> nodes_of_cut_cells(const mesh::LocalMesh& local, const mesh::Mesh& mesh,
                                    const mesh::DualMetrics& metrics, const Eigen::Vector3d& point,
                                    const Eigen::Vector3d& normal, const Eigen::Vector3d& lo,
                                    const Eigen::Vector3d& hi);
// Nodes inside the axis-aligned box [lo, hi].
std::vector<int> nodes_in_box(const mesh::LocalMesh& local, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi);

}  // namespace valsalva::analysis
