#include "analysis/probes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "core/comm.hpp"
#include "core/numeric_table.hpp"

namespace valsalva::analysis {

Probes::Probes(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
               const mesh::LocalMesh& local, std::vector<ProbePoint> points)
    : local_(&local), points_(std::move(points)) {
  const mesh::PointLocator locator(mesh);
  for (const auto& p : points_) {
    auto loc = locator.locate(p.position);
    if (!loc)
      throw std::runtime_error(fmt::format("probe '{}' at ({}, {}, {}) m is outside the mesh '{}'",
                                           p.name, p.position.x(), p.position.y(), p.position.z(),
                                           mesh.source));
    locations_.push_back(*loc);
    for (int k = 0; k < loc->count; ++k)
      needed_.push_back(metrics.dual_of_mesh_node[loc->nodes[k]]);
  }
  std::sort(needed_.begin(), needed_.end());
  needed_.erase(std::unique(needed_.begin(), needed_.end()), needed_.end());

  std::unordered_map<mesh::GlobalIndex, int> local_of_dual;
  for (int i = 0; i < local.num_owned; ++i) local_of_dual[local.dual_node[i]] = i;
  needed_local_.assign(needed_.size(), -1);
  for (std::size_t j = 0; j < needed_.size(); ++j)
    if (auto it = local_of_dual.find(needed_[j]); it != local_of_dual.end())
      needed_local_[j] = it->second;
  for (const auto& loc : locations_) {
    std::vector<int> s(loc.count);
    for (int k = 0; k < loc.count; ++k)
      s[k] = static_cast<int>(std::lower_bound(needed_.begin(), needed_.end(),
                                               metrics.dual_of_mesh_node[loc.nodes[k]]) -
                              needed_.begin());
    slot_.push_back(std::move(s));
  }
}

std::vector<double> Probes::sample(std::span<const double> values, int components) const {
  buffer_.assign(needed_.size() * components, 0.0);
  for (std::size_t j = 0; j < needed_.size(); ++j)
    if (needed_local_[j] >= 0)
      for (int c = 0; c < components; ++c)
        buffer_[j * components + c] = values[std::size_t(needed_local_[j]) * components + c];
  return gather_and_interpolate(components);
}

// Reads only the nodes the probes need (packing every owned node cost O(mesh) per sample).
std::vector<double> Probes::sample(const flow::FlowState& state) const {
  buffer_.assign(needed_.size() * 4, 0.0);
  for (std::size_t j = 0; j < needed_.size(); ++j)
    if (const int n = needed_local_[j]; n >= 0) {
      for (int c = 0; c < 3; ++c) buffer_[4 * j + c] = state.velocity[n][c];
      buffer_[4 * j + 3] = state.pressure[n];
    }
  return gather_and_interpolate(4);
}

std::vector<double> Probes::gather_and_interpolate(int components) const {
  // Exactly one rank owns each needed node; x + 0 is exact, so the sum is the owner's value.
  gathered_ = buffer_;
  local_->comm.sum_in_place(gathered_);
  std::vector<double> out(points_.size() * components, 0.0);
  for (std::size_t p = 0; p < points_.size(); ++p)
    for (int c = 0; c < components; ++c) {
      double s = 0;
      for (int k = 0; k < locations_[p].count; ++k)
        s += locations_[p].weights[k] * gathered_[slot_[p][k] * components + c];
      out[p * components + c] = s;
    }
  return out;
}

ProbeCsv::ProbeCsv(const std::filesystem::path& path, const Probes& probes,
                   std::vector<std::string> components, bool append)
    : path_(path), width_(probes.points().size() * components.size()) {
  if (!probes.comm().root()) return;
  out_.open(path, append ? std::ios::app : std::ios::trunc);
  if (!out_) throw std::runtime_error(fmt::format("probes: cannot write '{}'", path.string()));
  if (append) return;
  out_ << "time";
  for (const auto& p : probes.points())
    for (const auto& c : components) out_ << ',' << p.name << '_' << c;
  out_ << '\n';
  out_.flush();
}

void ProbeCsv::append(double time, const std::vector<double>& values) {
  if (!out_.is_open()) return;
  if (values.size() != width_)
    throw std::invalid_argument(fmt::format("probes '{}': {} values for {} columns", path_.string(),
                                            values.size(), width_));
  out_ << fmt::format("{:.17g}", time);
  for (double v : values) out_ << fmt::format(",{:.17g}", v);
  out_ << '\n';
  out_.flush();
}

std::vector<double> ProbeSeries::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end())
    throw std::runtime_error(fmt::format("probe file '{}': no column '{}'", source, name));
  const auto c = static_cast<std::size_t>(it - columns.begin());
  std::vector<double> out;
  for (const auto& r : rows) out.push_back(r[c]);
  return out;
}

// The shared strict reader (core/numeric_table.hpp): header required, finite values, unique
// column names, errors at FILE:LINE:COLUMN.
ProbeSeries read_probe_csv(const std::filesystem::path& path) {
  if (!std::ifstream(path))
    throw std::runtime_error(fmt::format("probe file '{}': cannot open", path.string()));
  auto table = core::read_numeric_table(path, core::TableHeader::required);
  if (table.columns.empty())
    throw std::runtime_error(fmt::format("probe file '{}': empty", path.string()));
  ProbeSeries s;
  s.source = table.source;
  s.columns = std::move(table.columns);
  s.rows = std::move(table.rows);
  return s;
}

}  // namespace valsalva::analysis
