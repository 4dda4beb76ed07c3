// Flow-rate waveforms Q(t) of velocity inlets, m^3/s: a constant, a sine
//   Q(t) = mean + amplitude sin(2 pi t / period + phase),
// or a table of (t, Q) rows (from a CSV file, io/waveform_table.hpp), linearly interpolated and
// repeated with the period t_last - t_first (the table covers one cycle; its last row should
// repeat the first Q, else Q jumps at the wrap). Any of them may start smoothly from rest: with
// ramp > 0, Q(t) is multiplied by (1 - cos(pi t / ramp)) / 2 for t < ramp (0 at t <= 0), the
// inflow ramp of the Turek-Hron benchmark.
#pragma once

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
  double ramp = 0;           // s; > 0: the smooth start (1 - cos(pi t / ramp)) / 2; 0 = none

  double operator()(double time) const;
};

// A table that is not one period of a waveform.
class WaveformError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The table waveform of rows (t_k, Q_k): at least two, t strictly increasing (else
// WaveformError naming the row, from 1). Files are read by io/waveform_table.hpp.
Waveform table_waveform(std::vector<double> t, std::vector<double> q);

}  // namespace valsalva::flow
