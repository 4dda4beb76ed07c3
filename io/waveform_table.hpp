// Inlet flow-rate tables: rows "t, Q" (s, m^3/s; comma, semicolon or blank separated) under an
// optional header of names, read by the strict table reader (core/numeric_table.hpp) into a
// flow::Waveform. Errors are TableError "FILE:LINE:COLUMN: what" (times not increasing, fewer
// than two rows, and everything the table reader refuses).
#pragma once

#include <filesystem>
#include <string>

#include "flow/inflow_waveform.hpp"

namespace valsalva::io {

flow::Waveform read_waveform_table(const std::filesystem::path& file);

// A table is repeated with its period t_last - t_first. When it is not one period (its last value
// differs from its first) and a run over [0, end_time] leaves [t_first, t_last], the value would
// jump where the table wraps: TableError naming `source`, the values and both ways out.
void check_table_wrap(const flow::Waveform& table, double end_time, const std::string& source);

}  // namespace valsalva::io
