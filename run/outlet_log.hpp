// outlets.csv: one row per step (and the initial state of a new run) with every lumped outlet's
// outward flux Q, pressure P and, for an RCR, distal pressure p_d, all to 17 digits, so that the
// lumped law can be checked from the file (log.csv carries the same every run.log_every steps,
// its fluxes to 10 digits). Written by rank 0; a resumed run appends (the restart has cut the
// rows after its checkpoint, run/restart_continuity.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flow/lumped_outlets.hpp"

namespace valsalva::run {

class OutletLog {
 public:
  // Opens <dir>/outlets.csv on the root rank (nothing elsewhere, or with an empty dir).
  OutletLog(const std::filesystem::path& dir, const flow::LumpedOutlets& outlets,
            const std::vector<std::string>& patch_names, bool root, bool append);
  void write(std::int64_t step, double time);

 private:
  const flow::LumpedOutlets& outlets_;
  std::ofstream file_;
};

}  // namespace valsalva::run
