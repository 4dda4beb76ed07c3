#include "io/waveform_table.hpp"

#include <fmt/format.h>

#include "io/numeric_table.hpp"

namespace valsalva::io {

flow::Waveform read_waveform_table(const std::filesystem::path& file) {
  const auto table = read_numeric_table(file, TableHeader::optional, 2, true);
  std::vector<double> t, q;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    if (k > 0 && !(table.rows[k][0] > t.back()))
      throw TableError(fmt::format("{}:{}:1: time {} is not after the previous row's {}",
                                   table.source, table.lines[k], table.rows[k][0], t.back()));
    t.push_back(table.rows[k][0]);
    q.push_back(table.rows[k][1]);
  }
  if (t.size() < 2)
    throw TableError(fmt::format("'{}': a waveform table needs at least two rows (t, Q), found {}",
                                 table.source, t.size()));
  return flow::table_waveform(std::move(t), std::move(q));
}

}  // namespace valsalva::io
