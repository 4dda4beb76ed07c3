// One reader for the numeric text tables valsalva reads (probe series for `psd`, inlet waveform
// tables, PIV CSV and Tecplot files, reference tables, phase lists): columns under an optional
// header, '#' comment lines and blank lines skipped. Strict, so that no input is read as
// something else without a word:
// - a header is recognised, never guessed: the first line is one when none of its fields is a
//   number and all are names; a first line mixing names and numbers (a typo in the first data
//   row, say) is an error, not a header;
// - every value is a finite number (no nan, inf, or overflow such as 1e999), except in the
//   columns a format declares maskable (PIV vectors), where an empty field or nan is a masked
//   value (NaN); inf and overflow stay refused there too;
// - column names are unique (case-insensitively), every row has the header's width;
// errors name FILE:LINE:COLUMN (column = character position of the field, from 1).
// Formats with more structure around their tables (Tecplot zones) read line by line with
// TableLines and get the same fields, numbers and messages.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace valsalva::core {

class TableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class TableHeader { required, optional, none };

struct TableFormat {
  TableHeader header = TableHeader::optional;
  std::size_t width = 0;         // > 0 fixes the number of columns (0: the first line decides)
  bool blank_separated = false;  // fields also separated by ';', blanks, tabs; empty ones skipped
  bool quoted = false;           // "double-quoted text" is one field, the quotes removed
  // Columns (by header name) whose empty or nan fields read as NaN: masked measurements.
  std::function<bool(const std::string&)> maskable;
};

struct TableField {
  std::string text;
  int column = 1;  // character position in the line, from 1
};

struct NumericTable {
  std::string source;                     // file name for messages
  std::vector<std::string> columns;       // empty without a header
  std::vector<std::vector<double>> rows;  // all of one width
  std::vector<int> lines;                 // line number of each row
  // The values of a named column; throws naming the file and the columns it has.
  std::vector<double> column(const std::string& name) const;
};

// The lines of a table file that are not blank or '#' comments, with the reader's fields,
// numbers and FILE:LINE:COLUMN errors.
class TableLines {
 public:
  TableLines(const std::filesystem::path& file, TableFormat format);  // throws: cannot open
  bool next();  // false at the end of the file
  int line() const { return line_; }
  const std::string& text() const { return text_; }
  const std::string& source() const { return source_; }
  // The fields of the line from character `from` on (columns still count from the line start).
  std::vector<TableField> fields(std::size_t from = 0) const;
  TableError error(int column, const std::string& what) const;
  // Whether every field is a column name (letters, digits, _ . ( ) / ^ - and blanks, not
  // starting with a digit) and some field is one.
  static bool all_names(const std::vector<TableField>& fields);
  // The names of a header line, each checked to be a name and unique (case-insensitively).
  std::vector<std::string> header(const std::vector<TableField>& fields) const;
  // The numbers of a data row; `names` (may be empty) label the columns in messages and decide
  // the maskable ones. Throws unless there are `width` fields (0: any number).
  std::vector<double> values(const std::vector<TableField>& fields,
                             const std::vector<std::string>& names, std::size_t width) const;
  // One number; `name` labels it in the message ("" = none).
  double number(const TableField& field, const std::string& name, bool maskable = false) const;

 private:
  std::ifstream in_;
  TableFormat format_;
  std::string source_, text_;
  int line_ = 0;
};

// Throws TableError.
NumericTable read_numeric_table(const std::filesystem::path& file, const TableFormat& format);
NumericTable read_numeric_table(const std::filesystem::path& file, TableHeader header,
                                std::size_t width = 0, bool blank_separated = false);

}  // namespace valsalva::core
