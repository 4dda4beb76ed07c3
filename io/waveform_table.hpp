// Inlet flow-rate tables: rows "t, Q" (s, m^3/s; comma, semicolon or blank separated) under an
// optional header of names, read by the strict table reader (io/numeric_table.hpp) into a
// flow::Waveform. Errors are TableError "FILE:LINE:COLUMN: what" (times not increasing, fewer
// than two rows, and everything the table reader refuses).
#pragma once

#include <filesystem>

#include "flow/inflow_waveform.hpp"

namespace valsalva::io {

flow::Waveform read_waveform_table(const std::filesystem::path& file);

}  // namespace valsalva::io
