// Planar PIV data: points (x, y) in the PIV plane's own frame with in-plane velocity (u, v),
// optionally the RMS (u_rms, v_rms), a validity flag, and a phase or time per frame. SI units
// (m, m/s): convert millimetre exports before reading. A point whose u or v is NaN, or whose
// `valid` flag is 0, is masked (kept, but skipped by comparisons).
//
// CSV: '#' comments and blank lines skipped; the first line names the columns (any order,
//   case-insensitive): x, y, u, v [, u_rms, v_rms] [, valid] [, phase | time]. Rows with the same
//   phase/time value form one frame, in order of first appearance. Empty fields read as NaN.
// Tecplot ASCII: TITLE (ignored), VARIABLES = "x" "y" "u" "v" ... (same names), then one ZONE per
//   frame: ZONE T="...", I=.., J=.. [, K=1] [, F=POINT | DATAPACKING=POINT] [, SOLUTIONTIME=..],
//   followed by I*J lines of one point each.
// Every malformed input throws std::runtime_error "PIV file '<path>' line <n>: <what>".
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::io {

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
// By extension: .csv -> CSV; .dat, .tec, .plt, .txt -> Tecplot ASCII.
PivData read_piv(const std::filesystem::path& path);

}  // namespace valsalva::io
