// outlets.csv of the lumped outlets; see outlet_log.hpp.
#include "run/outlet_log.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace valsalva::run {

OutletLog::OutletLog(const std::filesystem::path& dir, const flow::LumpedOutlets& outlets,
                     const std::vector<std::string>& patch_names, bool root, bool append)
    : outlets_(outlets) {
  if (!root || dir.empty()) return;
  const auto path = dir / "outlets.csv";
  std::error_code ec;
  const bool keep = append && std::filesystem::file_size(path, ec) > 0 && !ec;
  file_.open(path, keep ? std::ios::app : std::ios::trunc);
  if (!file_) throw std::runtime_error("flow run: cannot write " + path.string());
  if (keep) return;
  file_ << "step,time";
  for (int k = 0; k < outlets.count(); ++k) {
    const auto& name = patch_names[outlets.patch(k)];
    file_ << ",flux_" << name << ",pressure_" << name;
    if (const char* column = distal_column(outlets.spec(k).type)) file_ << "," << column << name;
  }
  file_ << "\n";
}

void OutletLog::write(std::int64_t step, double time) {
  if (!file_.is_open()) return;
  std::string row = fmt::format("{},{:.17g}", step, time);
  for (int k = 0; k < outlets_.count(); ++k) {
    const auto& s = outlets_.state(k);
    row += fmt::format(",{:.17g},{:.17g}", s.flux, s.pressure);
    if (distal_column(outlets_.spec(k).type)) row += fmt::format(",{:.17g}", s.distal);
  }
  file_ << row << "\n" << std::flush;
}

}  // namespace valsalva::run
