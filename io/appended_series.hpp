// The CSV series a run appends to (log.csv, probes.csv, valve.csv, ...) and cutting one back to
// a checkpoint, so that a restarted run does not repeat rows (run/restart_continuity.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::io {

// A CSV series appended to by a run, and whether its first column is the step (else the time).
struct AppendedSeries {
  std::string file;  // relative to the run directory
  bool by_step = false;
};

// The appended series of a run directory: log.csv, probes.csv, pressure_drop.csv,
// wall_shear_history.csv, structures.csv, outlets.csv, sections.csv, valve.csv
// (valve_cycles.csv is cut by the valve monitor, which knows the cycle open at the checkpoint).
const std::vector<AppendedSeries>& appended_series();

// Keeps the header line and the rows written up to the checkpoint: first column <= `step` (step
// series) or <= time + dt / 2 (time series: rows come one per step at most, so half the last
// step separates the checkpoint's row from the next one whatever digits were printed). A torn
// last line (a kill during the write) is dropped. Throws naming file and line when a row's first
// column is not a number. Returns the number of rows removed.
std::size_t truncate_series(const std::filesystem::path& file, bool by_step, std::int64_t step,
                            double time, double dt);

}  // namespace valsalva::io
