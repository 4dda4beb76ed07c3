// Appended CSV series of a run directory; see appended_series.hpp.
#include "io/appended_series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace valsalva::io {

namespace fs = std::filesystem;

const std::vector<AppendedSeries>& appended_series() {
  static const std::vector<AppendedSeries> series{{"log.csv", true},
                                                  {"probes.csv", false},
                                                  {"pressure_drop.csv", false},
                                                  {"wall_shear_history.csv", false},
                                                  {"structures.csv", true},
                                                  {"outlets.csv", true},
                                                  {"sections.csv", false},
                                                  {"valve.csv", true}};
  return series;
}

std::size_t truncate_series(const fs::path& file, bool by_step, std::int64_t step, double time,
                            double dt) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("restart: cannot read '{}'", file.string()));
  std::stringstream whole;
  whole << in.rdbuf();
  in.close();
  const std::string text = whole.str();
  std::string kept;
  std::size_t removed = 0, line_number = 0;
  bool cutting = false;  // rows are in order: after the first one beyond the checkpoint, all go
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = text.find('\n', begin);
    ++line_number;
    if (end == std::string::npos) {  // torn last line
      ++removed;
      break;
    }
    const std::string_view line(text.data() + begin, end - begin);
    const std::size_t next = end + 1;
    if (line_number == 1) {
      kept.append(line).push_back('\n');
      begin = next;
      continue;
    }
    const std::string_view first = line.substr(0, line.find(','));
    bool beyond = false;
    std::from_chars_result r{};
    if (by_step) {
      std::int64_t s = 0;
      r = std::from_chars(first.data(), first.data() + first.size(), s);
      beyond = s > step;
    } else {
      double t = 0;
      r = std::from_chars(first.data(), first.data() + first.size(), t);
      beyond = t > time + 0.5 * dt;
    }
    if (r.ec != std::errc() || r.ptr != first.data() + first.size())
      throw std::runtime_error(fmt::format("restart: '{}':{}: first column '{}' is not a {}",
                                           file.string(), line_number, first,
                                           by_step ? "step number" : "time"));
    cutting = cutting || beyond;
    if (cutting)
      ++removed;
    else
      kept.append(line).push_back('\n');
    begin = next;
  }
  if (removed > 0) {
    const fs::path tmp = fs::path(file.string() + ".tmp");
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << kept;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("restart: cannot write '{}'", tmp.string()));
    fs::rename(tmp, file);
  }
  return removed;
}

}  // namespace valsalva::io
