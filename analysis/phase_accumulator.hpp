// The mesh-free core of the phase statistics: per bin a sample count shared by all points, and
// per point the running mean of (u, v, w, p) and the sums of squared deviations M2 (uu, vv, ww,
// pp, uv, uw, vw), updated by Welford's algorithm, which stays accurate when the fluctuations
// are many orders below the mean (the naive sum of squares does not).
// B. P. Welford, Technometrics 4(3), 419-420, 1962; accumulators are merged with the pairwise
// formula of T. F. Chan, G. H. Golub, R. J. LeVeque, "Algorithms for computing the sample
// variance", The American Statistician 37(3), 242-247, 1983.
// A sample at time t goes to phase bin floor(frac((t - start) / period) * bins).
// Results: RMS = sqrt(M2/n) (population, as PIV ensemble statistics), Reynolds stresses
// <u_i' u_j'> = M2_ij / n in m^2/s^2, fluctuating kinetic energy k = rho/2 (u'^2+v'^2+w'^2) in
// J/m^3. period = 0 gives the plain time average (one bin).
// The points are whatever the owner says: mesh nodes (analysis::PhaseStatistics) or points on a
// line (analysis::LineStatistics); both save the accumulators through checkpoint_arrays()/restore()
// here.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"

namespace valsalva::analysis {

struct PhaseStatisticsOptions {
  double period = 0;           // s; 0 = plain time average (bins must be 1)
  int bins = 1;                // phase bins per period
  double start_time = 0;       // s; samples before it are ignored; phase 0 of cycle 0
  double density = 1;          // kg/m^3, for k
  std::string name = "stats";  // checkpoint array prefix and output basename, [A-Za-z0-9_]+
};

// Mean and second moments of one point in one bin.
struct NodeMoments {
  std::array<double, 4> mean{};  // u, v, w, p
  std::array<double, 7> m2{};    // uu, vv, ww, pp, uv, uw, vw (sums of squared deviations)
};

class PhaseAccumulator {
 public:
  static constexpr int per_node = 11;  // doubles per point and bin

  // Throws std::invalid_argument naming bad options.
  PhaseAccumulator(PhaseStatisticsOptions options, std::size_t points);

  const PhaseStatisticsOptions& options() const { return options_; }
  int bins() const { return options_.bins; }
  // Bin and cycle of time t (t >= start_time).
  int bin_of(double time) const;
  std::int64_t cycle_of(double time) const;
  // Centre of bin b as a time within the period (0 for the plain average).
  double phase_time(int bin) const;

  // Adds a sample to bin `bin` of cycle `cycle`: `values` holds u, v, w, p per point.
  void add_sample(int bin, std::int64_t cycle, std::span<const double> values);
  // Chan et al.'s pairwise merge of another accumulator over the same points and options.
  void merge(const PhaseAccumulator& other);

  std::int64_t count(int bin) const { return counts_[bin]; }
  // Cycles sampled: last cycle - first cycle + 1 (0 before any sample).
  std::int64_t cycles() const { return counts_total() ? last_cycle_ - first_cycle_ + 1 : 0; }
  NodeMoments moments(int bin, int i) const;
  double mean(int bin, int i, int q) const { return data_[offset(bin, i) + q]; }
  double rms(int bin, int i, int q) const;                     // q: 0 u, 1 v, 2 w, 3 p
  double reynolds_stress(int bin, int i, int a, int b) const;  // <u_a' u_b'>, a, b in 0..2
  double kinetic_energy(int bin, int i) const;                 // rho/2 (u'^2 + v'^2 + w'^2)

 protected:
  // Arrays <name>_moments (point i is row rows[i]; a rank may save fewer points than it has,
  // e.g. none when the points are replicated and rank 0 saves them), <name>_counts and
  // <name>_meta (saved by the root rank).
  std::vector<io::CheckpointArray> moment_arrays(std::span<const std::int64_t> rows,
                                                 std::int64_t global_rows, bool root) const;
  // Reads them back for point i = row rows[i] (every point of this accumulator). Throws naming
  // `where` when the options or the number of rows differ.
  void restore_moments(const io::CheckpointReader& reader, std::span<const std::int64_t> rows,
                       std::int64_t global_rows, const std::string& where);

  std::size_t offset(int bin, int i) const {
    return (std::size_t(bin) * points_ + std::size_t(i)) * per_node;
  }
  std::int64_t counts_total() const;

  PhaseStatisticsOptions options_;
  std::size_t points_ = 0;
  std::vector<std::int64_t> counts_;
  std::int64_t first_cycle_ = 0, last_cycle_ = 0;
  std::vector<double> data_;  // [bin][point][mean u v w p, m2 uu vv ww pp uv uw vw]
};

}  // namespace valsalva::analysis
