// Planar PIV data: points (x, y) in the PIV plane's own frame with in-plane velocity (u, v),
// optionally the RMS (u_rms, v_rms), a validity flag, and a phase or time per frame. SI units
// (m, m/s) after reading: files in other units (e.g. mm, mm/s) are read with PivUnits scale
// factors. A point whose u or v is NaN, or whose `valid` flag is 0, is masked (kept, but skipped
// by comparisons).
//
// CSV: '#' comments and blank lines skipped; the first line names the columns (any order,
//   case-insensitive): x, y, u, v [, u_rms, v_rms] [, valid] [, phase | time]. Rows with the same
//   phase/time value form one frame, in order of first appearance. Empty velocity fields read
//   as NaN (masked).
// Tecplot ASCII: TITLE (ignored), VARIABLES = "x" "y" "u" "v" ... (same names), then one ZONE per
//   frame: ZONE T="...", I=.., J=.. [, K=1] [, F=POINT | DATAPACKING=POINT] [, SOLUTIONTIME=..],
//   followed by I*J lines of one point each.
// Both are read with the strict table reader (core/numeric_table.hpp): every malformed input
// throws TableError "<path>:<line>:<column>: <what>"; x, y, valid and phase/time must be finite
// numbers, u, v, u_rms, v_rms finite or masked (empty or nan; inf and 1e999 are refused); column
// names are unique (case-insensitively); a zone holds exactly its I*J points.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::analysis {

struct PivFrame {
  std::string label;   // zone title, or "phase=<value>" / "time=<value>"
  double phase = NAN;  // phase or time value, NaN if the file has none
  int ni = 0, nj = 0;  // structured grid size (Tecplot), 0 when unknown
  std::vector<double> x, y, u, v;
  std::vector<double> u_rms, v_rms;  // empty when the file has no RMS
  std::vector<std::uint8_t> valid;   // 1 = usable, 0 = masked or NaN
  std::size_t size() const { return x.size(); }
  std::size_t valid_count() const;
};

struct PivData {
  std::string source;
  std::string frame_key;  // "phase", "time" or "" (single frame)
  bool has_rms = false;
  std::vector<PivFrame> frames;
};

PivData read_piv_csv(const std::filesystem::path& path);
PivData read_piv_tecplot(const std::filesystem::path& path);
// Factors that turn the file's numbers into SI: x, y times `length` [m per file unit]; u, v,
// u_rms, v_rms times `velocity` [m/s per file unit]. Phase/time values are not scaled.
struct PivUnits {
  double length = 1, velocity = 1;  // 0.001 and 0.001 for mm and mm/s
};
// Multiplies in place; throws std::invalid_argument unless both factors are finite and > 0.
void scale_piv(PivData& data, const PivUnits& units);

// By extension: .csv -> CSV; .dat, .tec, .plt, .txt -> Tecplot ASCII; then scale_piv.
PivData read_piv(const std::filesystem::path& path, const PivUnits& units = {});

}  // namespace valsalva::analysis
