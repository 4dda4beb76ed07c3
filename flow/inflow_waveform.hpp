// Flow-rate waveforms Q(t) of velocity inlets, m^3/s: a constant, a sine
//   Q(t) = mean + amplitude sin(2 pi t / period + phase),
// or a table of (t, Q) rows from a CSV file, linearly interpolated and repeated with the period
// t_last - t_first (the table covers one cycle; its last row should repeat the first Q, else Q
// jumps at the wrap).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace valsalva::flow {

struct Waveform {
  enum class Kind { constant, sine, table };
  Kind kind = Kind::constant;
  double mean = 0;           // m^3/s (constant and sine)
  double amplitude = 0;      // m^3/s (sine)
  double period = 1;         // s (sine; tables: t_last - t_first)
  double phase = 0;          // rad (sine)
  std::vector<double> t, q;  // table rows, t strictly increasing

  double operator()(double time) const;
};

// A malformed waveform file: what() is "FILE:LINE: problem".
class WaveformError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads "t, Q" rows (comma, semicolon or blank separated). Blank lines and lines starting with
// '#' are skipped; the first other line may be a header (its first field is not a number).
// At least two rows, t strictly increasing, finite numbers; errors name the file and line.
Waveform read_waveform_csv(const std::filesystem::path& file);

}  // namespace valsalva::flow
