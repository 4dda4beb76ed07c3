// Phase-averaged statistics over cardiac cycles, accumulated on the fly. A sample at time t goes
// to phase bin floor(frac((t - start) / period) * bins); per bin the sample count is shared by
// all nodes, and per node the running mean of (u, v, w, p) and the sums of squared deviations
// M2 (uu, vv, ww, pp, uv, uw, vw) are updated by Welford's algorithm, which stays accurate when
// the fluctuations are many orders below the mean (the naive sum of squares does not).
// B. P. Welford, Technometrics 4(3), 419-420, 1962; accumulators are merged with the pairwise
// formula of T. F. Chan, G. H. Golub, R. J. LeVeque, "Algorithms for computing the sample
// variance", The American Statistician 37(3), 242-247, 1983.
// Results: RMS = sqrt(M2/n) (population, as PIV ensemble statistics), Reynolds stresses
// <u_i' u_j'> = M2_ij / n in m^2/s^2, fluctuating kinetic energy k = rho/2 (u'^2+v'^2+w'^2) in
// J/m^3. period = 0 gives the plain time average (one bin).
// Memory: 11 doubles = 88 bytes per node and bin (a 1 M-node mesh, 20 bins: 1.76 GB over all
// ranks) plus 44 bytes per covered node; checkpoint_arrays() copies the moments once more while
// a checkpoint is written. Restrict `nodes` to planes or regions to save it (docs/analysis.md).
//
// How the run loop uses it:
//   io::PhaseStatistics stats(local, {period, bins, t_start, rho, "stats"},
//                             io::nodes_near_plane(local, p0, n, 0.5e-3));   // or all_owned_nodes
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

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "io/checkpoint.hpp"

namespace valsalva::io {

struct PhaseStatisticsOptions {
  double period = 0;           // s; 0 = plain time average (bins must be 1)
  int bins = 1;                // phase bins per period
  double start_time = 0;       // s; samples before it are ignored; phase 0 of cycle 0
  double density = 1;          // kg/m^3, for k
  std::string name = "stats";  // checkpoint array prefix and output basename, [A-Za-z0-9_]+
};

// Mean and second moments of one node in one bin.
struct NodeMoments {
  std::array<double, 4> mean{};  // u, v, w, p
  std::array<double, 7> m2{};    // uu, vv, ww, pp, uv, uw, vw (sums of squared deviations)
};

class PhaseStatistics {
 public:
  static constexpr int per_node = 11;  // doubles per node and bin

  // `nodes`: owned local node indices covered (any order, unique). Throws naming bad options.
  PhaseStatistics(const flow::LocalMesh& local, PhaseStatisticsOptions options,
                  std::vector<int> nodes);

  const PhaseStatisticsOptions& options() const { return options_; }
  const std::vector<int>& nodes() const { return nodes_; }
  int bins() const { return options_.bins; }
  // Bin and cycle of time t (t >= start_time).
  int bin_of(double time) const;
  std::int64_t cycle_of(double time) const;
  // Centre of bin b as a time within the period (0 for the plain average).
  double phase_time(int bin) const;

  // Adds the sample of every covered node (local arrays, owned first). Ignored before start.
  void add(double time, const flow::VectorField& velocity, const flow::ScalarField& pressure);
  // Adds a sample to bin `bin` of cycle `cycle`: `values` holds u, v, w, p per covered node.
  void add_sample(int bin, std::int64_t cycle, std::span<const double> values);
  // Chan et al.'s pairwise merge of another accumulator over the same nodes and options.
  void merge(const PhaseStatistics& other);

  std::int64_t count(int bin) const { return counts_[bin]; }
  // Cycles sampled: last cycle - first cycle + 1 (0 before any sample).
  std::int64_t cycles() const { return counts_total() ? last_cycle_ - first_cycle_ + 1 : 0; }
  NodeMoments moments(int bin, int i) const;  // i indexes nodes()
  double mean(int bin, int i, int q) const { return data_[offset(bin, i) + q]; }
  double rms(int bin, int i, int q) const;                     // q: 0 u, 1 v, 2 w, 3 p
  double reynolds_stress(int bin, int i, int a, int b) const;  // <u_a' u_b'>, a, b in 0..2
  double kinetic_energy(int bin, int i) const;                 // rho/2 (u'^2 + v'^2 + w'^2)

  // Accumulators as checkpoint arrays <name>_moments, _counts, _meta, _nodes; rows of the
  // moments are the covered nodes numbered by increasing dual id over all ranks.
  std::vector<CheckpointArray> checkpoint_arrays() const;
  // Collective. Throws naming the checkpoint when options or covered nodes differ.
  void restore(const CheckpointReader& reader);

  // Collective. Writes <dir>/<name>.xmf + HDF5 (one XDMF step per bin at its phase time; fields
  // mean_velocity, mean_pressure, rms_velocity, rms_pressure, reynolds_uv, reynolds_uw,
  // reynolds_vw, k; NaN outside the covered nodes) and <dir>/<name>_phases.csv (bin,
  // phase_time, samples, cycles). Returns the .xmf path.
  std::filesystem::path write(const flow::Mesh& mesh, const flow::DualMetrics& metrics,
                              const std::filesystem::path& dir) const;

 private:
  std::size_t offset(int bin, int i) const {
    return (std::size_t(bin) * nodes_.size() + std::size_t(i)) * per_node;
  }
  std::int64_t counts_total() const;

  const flow::LocalMesh* local_;
  PhaseStatisticsOptions options_;
  std::vector<int> nodes_;
  std::vector<std::int64_t> rows_;  // global subset row of every covered node
  std::int64_t global_rows_ = 0;
  std::vector<std::int64_t> counts_;
  std::int64_t first_cycle_ = 0, last_cycle_ = 0;
  std::vector<double> data_;  // [bin][node][mean u v w p, m2 uu vv ww pp uv uw vw]
  std::vector<double> sample_;
};

// Covered-node selections (owned local indices).
std::vector<int> all_owned_nodes(const flow::LocalMesh& local);
// Nodes within `half_thickness` of the plane through `point` with normal `normal`.
std::vector<int> nodes_near_plane(const flow::LocalMesh& local, const Eigen::Vector3d& point,
                                  const Eigen::Vector3d& normal, double half_thickness);
// Nodes inside the axis-aligned box [lo, hi].
std::vector<int> nodes_in_box(const flow::LocalMesh& local, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi);

}  // namespace valsalva::io
