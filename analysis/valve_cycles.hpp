// Per-cycle indices of a valve from its per-step samples: transvalvular pressure gradient
// extremes, forward and regurgitant volumes (closing and leakage), and the opening, fully-open
// and closing instants.
//
// Definitions (after ISO 5840-2 and the reference pulse-duplicator study, valve_case.md):
//   Q(t) the flow through the valve, positive forward (towards the aorta);
//   forward volume   = int max(Q, 0) dt over the cycle;
//   regurgitant volume = int max(-Q, 0) dt = closing volume + leakage volume, split at the
//     closing instant: backflow before it passes while the valve closes, after it through the
//     closed valve;
//   opening start / fully open: the first samples whose opening ratio reaches open_fraction /
//     full_fraction of the cycle's swing, from its smallest ratio (the closed orifice; not zero
//     when a contact clearance holds the leaflets apart) to its largest; closing: the first
//     sample after the largest opening whose ratio falls back to open_fraction of the swing
//     (NaN when it does not);
//   TPG_max the largest gradient while Q > 0, TPG_min the smallest while Q < 0 (NaN without
//     such samples).
// Integrals use the trapezoidal rule between consecutive samples of the cycle.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace valsalva::analysis {

struct ValveSample {
  double time = 0;           // s
  double flow = 0;           // m^3/s, forward positive
  double tpg = 0;            // mmHg, upstream minus downstream
  double opening_ratio = 0;  // geometric orifice area / annulus area
  double max_von_mises = 0;  // Pa
};
inline constexpr int valve_sample_fields = 5;

struct CycleSummary {
  int cycle = 0;
  double start = 0, end = 0;  // s
  double tpg_max = 0, tpg_min = 0;
  double forward_volume = 0, regurgitant_volume = 0, closing_volume = 0, leakage_volume = 0;
  double max_opening_ratio = 0, min_opening_ratio = 0;
  double opening_start = 0, fully_open = 0, closing = 0;  // s, NaN when not reached
  double max_von_mises = 0;
  int samples = 0;
};

struct CycleOptions {
  double period = 1;      // s
  double start_time = 0;  // s, phase 0 of cycle 0
  double open_fraction = 0.05;
  double full_fraction = 0.9;
};

// The summary of one cycle's samples (time-ordered, at least two).
CycleSummary summarise_cycle(int cycle, std::span<const ValveSample> samples,
                             const CycleOptions& options);

// Collects samples and closes a cycle when a sample falls in a later one (the boundary sample
// is shared: it ends one cycle and starts the next). Samples before start_time are ignored.
class CycleTracker {
 public:
  explicit CycleTracker(const CycleOptions& options);
  // The summary of the cycle this sample completes, if any.
  std::optional<CycleSummary> add(const ValveSample& s);
  // The open cycle's samples as a flat array (valve_sample_fields per sample) and back, for
  // checkpoints.
  std::vector<double> state() const;
  void restore(std::span<const double> flat);
  int cycle_of(double time) const;
  const std::vector<ValveSample>& open_samples() const { return samples_; }

 private:
  CycleOptions options_;
  std::vector<ValveSample> samples_;
};

}  // namespace valsalva::analysis
