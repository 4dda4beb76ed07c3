// One reader for the numeric text tables valsalva reads (probe series for `psd`, inlet waveform
// tables, phase lists): comma-separated columns under an optional header, '#' comment lines and
// blank lines skipped. Strict, so that no input is read as something else without a word:
// - a header is recognised, never guessed: the first line is one when none of its fields is a
//   number and all are names; a first line mixing names and numbers (a typo in the first data
//   row, say) is an error, not a header;
// - every value is a finite number (no nan, inf, or overflow such as 1e999);
// - column names are unique, every row has the header's width;
// errors name FILE:LINE:COLUMN (column = character position of the field, from 1).
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace valsalva::io {

class TableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class TableHeader { required, optional, none };

struct NumericTable {
  std::string source;                     // file name for messages
  std::vector<std::string> columns;       // empty without a header
  std::vector<std::vector<double>> rows;  // all of one width
  std::vector<int> lines;                 // line number of each row
  // The values of a named column; throws naming the file and the columns it has.
  std::vector<double> column(const std::string& name) const;
};

// Throws TableError. `width` > 0 fixes the number of columns (0: the first line decides).
// `blank_separated`: fields may also be separated by ';', blanks or tabs, empty fields skipped
// (the inlet waveform tables' format).
NumericTable read_numeric_table(const std::filesystem::path& file, TableHeader header,
                                std::size_t width = 0, bool blank_separated = false);

}  // namespace valsalva::io
