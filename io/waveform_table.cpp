#include "io/waveform_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/numeric_table.hpp"

namespace valsalva::io {

flow::Waveform read_waveform_table(const std::filesystem::path& file) {
  const auto table = core::read_numeric_table(file, core::TableHeader::optional, 2, true);
  std::vector<double> t, q;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    if (k > 0 && !(table.rows[k][0] > t.back()))
      throw core::TableError(fmt::format("{}:{}:1: time {} is not after the previous row's {}",
                                         table.source, table.lines[k], table.rows[k][0], t.back()));
    t.push_back(table.rows[k][0]);
    q.push_back(table.rows[k][1]);
  }
  if (t.size() < 2)
    throw core::TableError(fmt::format(
        "'{}': a waveform table needs at least two rows (t, Q), found {}", table.source, t.size()));
  return flow::table_waveform(std::move(t), std::move(q));
}

void check_table_wrap(const flow::Waveform& table, double end_time, const std::string& source) {
  double largest = 0;
  for (double q : table.q) largest = std::max(largest, std::abs(q));
  const double first = table.q.front(), last = table.q.back();
  // Round-off of a printed table (9+ digits) is far below this; a real mismatch is not.
  if (std::abs(last - first) <= 1e-6 * largest) return;
  const double t0 = table.t.front(), t1 = table.t.back();
  if (t0 <= 0 && end_time <= t1) return;
  throw core::TableError(fmt::format(
      "'{}' is not one period (its last value {} at t = {} s differs from its first, {} at t = {} "
      "s) and the run ({} to {} s) goes beyond it: the table is repeated with period {} s, so "
      "the value would jump where it wraps. Make the last row repeat the first value, or let "
      "the table cover the whole run (rows from t <= 0 to t >= time.end)",
      source, last, t1, first, t0, 0.0, end_time, t1 - t0));
}

}  // namespace valsalva::io
