#include "io/phase_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <regex>
#include <stdexcept>

#include "io/field_output.hpp"

namespace valsalva::io {

namespace {

// Index of the M2 entry of the pair (a, b), a, b in 0..3 (3 = p; p only with itself).
constexpr int m2_index(int a, int b) {
  if (a > b) std::swap(a, b);
  if (a == b) return a;               // uu vv ww pp
  if (a == 0) return b == 1 ? 4 : 5;  // uv uw
  return 6;                           // vw
}

// All ranks' ids, sorted (every rank gets the same list).
std::vector<std::int64_t> gather_sorted(const flow::Comm& comm,
                                        const std::vector<std::int64_t>& mine) {
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(comm.size()), displs(comm.size(), 0);
  VALSALVA_MPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm.get()));
  std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  std::vector<std::int64_t> all(std::accumulate(counts.begin(), counts.end(), std::size_t(0)));
  VALSALVA_MPI(MPI_Allgatherv(mine.data(), n, MPI_INT64_T, all.data(), counts.data(), displs.data(),
                              MPI_INT64_T, comm.get()));
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

PhaseStatistics::PhaseStatistics(const flow::LocalMesh& local, PhaseStatisticsOptions options,
                                 std::vector<int> nodes)
    : local_(&local), options_(std::move(options)), nodes_(std::move(nodes)) {
  const auto& o = options_;
  if (o.bins < 1) throw std::invalid_argument(fmt::format("statistics: bins = {} < 1", o.bins));
  if (o.period < 0 || !std::isfinite(o.period) || (o.period == 0 && o.bins != 1))
    throw std::invalid_argument(fmt::format(
        "statistics: period = {} s with bins = {} (period 0 means a plain average, 1 bin)",
        o.period, o.bins));
  if (!(o.density > 0))
    throw std::invalid_argument(fmt::format("statistics: density = {} kg/m^3", o.density));
  if (!std::regex_match(o.name, std::regex("[A-Za-z0-9_]+")))
    throw std::invalid_argument(fmt::format("statistics: name '{}' is not [A-Za-z0-9_]+", o.name));
  std::vector<std::int64_t> ids;
  for (int i : nodes_) {
    if (i < 0 || i >= local.num_owned)
      throw std::invalid_argument(fmt::format("statistics: node {} is not owned", i));
    ids.push_back(local.dual_node[i]);
  }
  const auto all = gather_sorted(local.comm, ids);
  if (std::adjacent_find(all.begin(), all.end()) != all.end())
    throw std::invalid_argument("statistics: a node is listed twice");
  global_rows_ = static_cast<std::int64_t>(all.size());
  for (auto id : ids) rows_.push_back(std::lower_bound(all.begin(), all.end(), id) - all.begin());
  counts_.assign(o.bins, 0);
  data_.assign(std::size_t(o.bins) * nodes_.size() * per_node, 0.0);
  sample_.resize(nodes_.size() * 4);
}

double PhaseStatistics::phase_time(int bin) const {
  return options_.period * (bin + 0.5) / options_.bins;
}

std::int64_t PhaseStatistics::cycle_of(double time) const {
  if (options_.period == 0) return 0;
  return static_cast<std::int64_t>(std::floor((time - options_.start_time) / options_.period));
}

int PhaseStatistics::bin_of(double time) const {
  if (options_.period == 0) return 0;
  const double cycles = (time - options_.start_time) / options_.period;
  const double phase = cycles - std::floor(cycles);  // [0, 1)
  return std::min(options_.bins - 1, static_cast<int>(phase * options_.bins));
}

void PhaseStatistics::add(double time, const flow::VectorField& velocity,
                          const flow::ScalarField& pressure) {
  if (time < options_.start_time) return;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const int n = nodes_[i];
    for (int c = 0; c < 3; ++c) sample_[4 * i + c] = velocity[n][c];
    sample_[4 * i + 3] = pressure[n];
  }
  add_sample(bin_of(time), cycle_of(time), sample_);
}

void PhaseStatistics::add_sample(int bin, std::int64_t cycle, std::span<const double> values) {
  if (bin < 0 || bin >= options_.bins || values.size() != nodes_.size() * 4)
    throw std::invalid_argument(
        fmt::format("statistics: bad sample (bin {}, {} values for {} nodes)", bin, values.size(),
                    nodes_.size()));
  if (counts_total() == 0) first_cycle_ = last_cycle_ = cycle;
  first_cycle_ = std::min(first_cycle_, cycle);
  last_cycle_ = std::max(last_cycle_, cycle);
  const double inv_n = 1.0 / double(++counts_[bin]);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    double* m = data_.data() + offset(bin, int(i));
    double d[4], e[4];  // deviation from the old mean, from the new mean
    for (int q = 0; q < 4; ++q) {
      const double x = values[4 * i + q];
      d[q] = x - m[q];
      m[q] += d[q] * inv_n;
      e[q] = x - m[q];
    }
    double* m2 = m + 4;
    m2[0] += d[0] * e[0], m2[1] += d[1] * e[1], m2[2] += d[2] * e[2], m2[3] += d[3] * e[3];
    m2[4] += d[0] * e[1], m2[5] += d[0] * e[2], m2[6] += d[1] * e[2];
  }
}

void PhaseStatistics::merge(const PhaseStatistics& other) {
  if (other.nodes_ != nodes_ || other.options_.bins != options_.bins ||
      other.options_.period != options_.period)
    throw std::invalid_argument("statistics: merge of accumulators over other nodes or bins");
  if (other.counts_total() == 0) return;
  if (counts_total() == 0) {
    first_cycle_ = other.first_cycle_, last_cycle_ = other.last_cycle_;
  } else {
    first_cycle_ = std::min(first_cycle_, other.first_cycle_);
    last_cycle_ = std::max(last_cycle_, other.last_cycle_);
  }
  for (int b = 0; b < options_.bins; ++b) {
    const double na = double(counts_[b]), nb = double(other.counts_[b]), n = na + nb;
    if (nb == 0) continue;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      double* a = data_.data() + offset(b, int(i));
      const double* o = other.data_.data() + other.offset(b, int(i));
      double delta[4];
      for (int q = 0; q < 4; ++q) delta[q] = o[q] - a[q];
      const double w = na * nb / n;
      a[4] += o[4] + delta[0] * delta[0] * w, a[5] += o[5] + delta[1] * delta[1] * w;
      a[6] += o[6] + delta[2] * delta[2] * w, a[7] += o[7] + delta[3] * delta[3] * w;
      a[8] += o[8] + delta[0] * delta[1] * w, a[9] += o[9] + delta[0] * delta[2] * w;
      a[10] += o[10] + delta[1] * delta[2] * w;
      for (int q = 0; q < 4; ++q) a[q] += delta[q] * nb / n;
    }
    counts_[b] += other.counts_[b];
  }
}

std::int64_t PhaseStatistics::counts_total() const {
  return std::accumulate(counts_.begin(), counts_.end(), std::int64_t(0));
}

NodeMoments PhaseStatistics::moments(int bin, int i) const {
  NodeMoments m;
  const double* p = data_.data() + offset(bin, i);
  std::copy(p, p + 4, m.mean.begin());
  std::copy(p + 4, p + 11, m.m2.begin());
  return m;
}

double PhaseStatistics::rms(int bin, int i, int q) const {
  if (counts_[bin] == 0) return NAN;
  return std::sqrt(std::max(0.0, data_[offset(bin, i) + 4 + q] / double(counts_[bin])));
}

double PhaseStatistics::reynolds_stress(int bin, int i, int a, int b) const {
  if (counts_[bin] == 0) return NAN;
  return data_[offset(bin, i) + 4 + m2_index(a, b)] / double(counts_[bin]);
}

double PhaseStatistics::kinetic_energy(int bin, int i) const {
  if (counts_[bin] == 0) return NAN;
  const double* m2 = data_.data() + offset(bin, i) + 4;
  return 0.5 * options_.density * (m2[0] + m2[1] + m2[2]) / double(counts_[bin]);
}

std::vector<CheckpointArray> PhaseStatistics::checkpoint_arrays() const {
  const int cols = options_.bins * per_node;
  CheckpointArray moments{options_.name + "_moments", global_rows_, cols, rows_, {}};
  moments.data.resize(nodes_.size() * cols);
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (int b = 0; b < options_.bins; ++b)
      std::copy_n(data_.data() + offset(b, int(i)), per_node,
                  moments.data.data() + i * cols + std::size_t(b) * per_node);
  CheckpointArray nodes{options_.name + "_nodes", global_rows_, 0, rows_, {}};
  for (int i : nodes_) nodes.data.push_back(double(local_->dual_node[i]));
  CheckpointArray counts{options_.name + "_counts", options_.bins, 0, {}, {}};
  CheckpointArray meta{options_.name + "_meta", 6, 0, {}, {}};
  if (local_->comm.root()) {
    for (int b = 0; b < options_.bins; ++b) {
      counts.rows.push_back(b);
      counts.data.push_back(double(counts_[b]));
    }
    meta.rows = {0, 1, 2, 3, 4, 5};
    meta.data = {options_.period,      double(options_.bins), options_.start_time,
                 double(first_cycle_), double(last_cycle_),   double(global_rows_)};
  }
  // Moved, not copied: an initializer list would copy the moments (gigabytes on a whole mesh).
  std::vector<CheckpointArray> arrays;
  for (auto* a : {&moments, &nodes, &counts, &meta}) arrays.push_back(std::move(*a));
  return arrays;
}

void PhaseStatistics::restore(const CheckpointReader& reader) {
  const std::string where =
      fmt::format("checkpoint '{}', statistics '{}'", reader.path().string(), options_.name);
  const std::vector<std::int64_t> meta_rows = {0, 1, 2, 3, 4, 5};
  const auto meta = reader.read_array(options_.name + "_meta", meta_rows);
  if (meta[0] != options_.period || meta[1] != options_.bins || meta[2] != options_.start_time ||
      meta[5] != double(global_rows_))
    throw std::runtime_error(fmt::format(
        "{}: saved with period {} s, {} bins, start {} s, {} nodes; this run has {} s, {}, {} s, "
        "{}",
        where, meta[0], meta[1], meta[2], meta[5], options_.period, options_.bins,
        options_.start_time, global_rows_));
  const auto ids = reader.read_array(options_.name + "_nodes", rows_);
  int wrong = 0;
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    wrong += ids[i] != double(local_->dual_node[nodes_[i]]);
  if (local_->comm.sum(std::int64_t(wrong)) != 0)
    throw std::runtime_error(fmt::format("{}: the covered nodes differ", where));
  std::vector<std::int64_t> bin_rows(options_.bins);
  std::iota(bin_rows.begin(), bin_rows.end(), 0);
  const auto counts = reader.read_array(options_.name + "_counts", bin_rows);
  for (int b = 0; b < options_.bins; ++b) counts_[b] = std::int64_t(counts[b]);
  first_cycle_ = std::int64_t(meta[3]), last_cycle_ = std::int64_t(meta[4]);
  const auto moments = reader.read_array(options_.name + "_moments", rows_);
  const int cols = options_.bins * per_node;
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (int b = 0; b < options_.bins; ++b)
      std::copy_n(moments.data() + i * cols + std::size_t(b) * per_node, per_node,
                  data_.data() + offset(b, int(i)));
}

std::filesystem::path PhaseStatistics::write(const flow::Mesh& mesh,
                                             const flow::DualMetrics& metrics,
                                             const std::filesystem::path& dir) const {
  const auto& local = *local_;
  if (local.comm.root()) std::filesystem::create_directories(dir);
  local.comm.barrier();
  FieldOutput out(mesh, metrics, local, dir, options_.name);
  const std::size_t n = local.num_local();
  const Eigen::Vector3d nan3 = Eigen::Vector3d::Constant(NAN);
  std::vector<Eigen::Vector3d> mean_u(n, nan3), rms_u(n, nan3);
  std::vector<double> mean_p(n, NAN), rms_p(n, NAN), uv(n, NAN), uw(n, NAN), vw(n, NAN), k(n, NAN);
  for (int b = 0; b < options_.bins; ++b) {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const int j = nodes_[i];
      mean_u[j] = {mean(b, int(i), 0), mean(b, int(i), 1), mean(b, int(i), 2)};
      rms_u[j] = {rms(b, int(i), 0), rms(b, int(i), 1), rms(b, int(i), 2)};
      mean_p[j] = mean(b, int(i), 3), rms_p[j] = rms(b, int(i), 3);
      uv[j] = reynolds_stress(b, int(i), 0, 1), uw[j] = reynolds_stress(b, int(i), 0, 2);
      vw[j] = reynolds_stress(b, int(i), 1, 2), k[j] = kinetic_energy(b, int(i));
    }
    out.write(phase_time(b),
              {{"mean_pressure", &mean_p},
               {"rms_pressure", &rms_p},
               {"reynolds_uv", &uv},
               {"reynolds_uw", &uw},
               {"reynolds_vw", &vw},
               {"k", &k}},
              {{"mean_velocity", &mean_u}, {"rms_velocity", &rms_u}});
  }
  if (local.comm.root()) {
    std::ofstream csv(dir / (options_.name + "_phases.csv"));
    csv << "bin,phase_time,samples,cycles\n";
    for (int b = 0; b < options_.bins; ++b)
      csv << fmt::format("{},{:.17g},{},{}\n", b, phase_time(b), counts_[b], cycles());
    if (!csv)
      throw std::runtime_error(fmt::format("statistics: cannot write '{}'",
                                           (dir / (options_.name + "_phases.csv")).string()));
  }
  return out.xmf_file();
}

std::vector<int> all_owned_nodes(const flow::LocalMesh& local) {
  std::vector<int> v(local.num_owned);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

std::vector<int> nodes_near_plane(const flow::LocalMesh& local, const Eigen::Vector3d& point,
                                  const Eigen::Vector3d& normal, double half_thickness) {
  const Eigen::Vector3d n = normal.normalized();
  std::vector<int> v;
  for (int i = 0; i < local.num_owned; ++i)
    if (std::abs((local.position[i] - point).dot(n)) <= half_thickness) v.push_back(i);
  return v;
}

std::vector<int> nodes_in_box(const flow::LocalMesh& local, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi) {
  std::vector<int> v;
  for (int i = 0; i < local.num_owned; ++i)
    if ((local.position[i].array() >= lo.array()).all() &&
        (local.position[i].array() <= hi.array()).all())
      v.push_back(i);
  return v;
}

}  // namespace valsalva::io
