#include "analysis/wall_shear_recorder.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "analysis/wall_shear_rows.hpp"
#include "analysis/wall_shear_summary.hpp"
#include "analysis/wall_shear_surface.hpp"
#include "flow/wall_force.hpp"

namespace valsalva::analysis {

namespace {

constexpr int wss_cols = 4;  // sum tau_x dt, sum tau_y dt, sum tau_z dt, sum |tau| dt

}  // namespace

WallShearRecorder::WallShearRecorder(const mesh::LocalMesh& local, WallShearOptions options,
                                     double density, double dynamic_viscosity,
                                     const std::filesystem::path& run_dir, bool append)
    : local_(&local),
      options_(std::move(options)),
      density_(density),
      mu_(dynamic_viscosity),
      weights_(flow::laplacian_weights(local)) {
  // The wall nodes of each patch, in the order wall_loads returns them (state-independent).
  const auto n = static_cast<std::size_t>(local.num_local());
  const flow::VectorField zero_v(n, Eigen::Vector3d::Zero());
  const flow::ScalarField zero_p(n, 0.0);
  const flow::TensorField zero_g(n, Eigen::Matrix3d::Zero());
  for (const auto& patch : options_.patches) {
    if (std::find(local.patch_names.begin(), local.patch_names.end(), patch) ==
        local.patch_names.end())
      throw std::runtime_error(fmt::format("wall_shear: patch '{}' is not in the mesh", patch));
    flow::WallForceInput in;
    in.density = density_;
    in.dynamic_viscosity = mu_;
    in.velocity = &zero_v;
    in.pressure = &zero_p;
    in.velocity_gradient = &zero_g;
    in.laplacian_weights = &weights_;
    std::vector<int> nodes;
    std::vector<double> area;
    for (const auto& l : flow::wall_loads(local, patch, in)) {
      nodes.push_back(l.node);
      area.push_back(l.area.norm());
    }
    nodes_.push_back(std::move(nodes));
    area_.push_back(std::move(area));
  }
  tau_.resize(options_.patches.size());
  stats_.resize(options_.patches.size());
  support_time_.resize(options_.patches.size());
  for (std::size_t p = 0; p < nodes_.size(); ++p) support_time_[p].assign(nodes_[p].size(), 0.0);
  if (local.comm.root()) {
    const auto path = run_dir / "wall_shear_history.csv";
    history_.open(path, append ? std::ios::app : std::ios::trunc);
    if (!history_) throw std::runtime_error("wall_shear: cannot write " + path.string());
    if (!append) {
      history_ << "time";
      for (const auto& p : options_.patches) history_ << ',' << p << "_mean_wss";
      history_ << '\n';
    }
  }
}

void WallShearRecorder::sample(const flow::FlowState& state) {
  flow::gradient(*local_, state.velocity, grad_);
  flow::WallForceInput in;
  in.density = density_;
  in.dynamic_viscosity = mu_;
  in.velocity = &state.velocity;
  in.pressure = &state.pressure;
  in.velocity_gradient = &grad_;
  in.laplacian_weights = &weights_;
  in.body_force = body_force_;
  if (model_.law != flow::ViscosityLaw::newtonian) {
    mu_field_.resize(grad_.size());
    for (std::size_t i = 0; i < grad_.size(); ++i)
      mu_field_[i] = flow::apparent_viscosity(model_, flow::shear_rate(grad_[i]));
    in.viscosity_field = &mu_field_;
  }
  const double t = state.time, t0 = options_.start_time;
  const double elapsed = sampled_ ? t - std::max(last_time_, t0) : 0.0;
  const bool accumulate = t > t0 && elapsed > 0;
  if (accumulate && support_nodes_) support_nodes_(in_support_);
  std::vector<double> mean;
  for (std::size_t p = 0; p < options_.patches.size(); ++p) {
    std::vector<Eigen::Vector3d> previous =
        flow::wall_shear_stress(flow::wall_loads(*local_, options_.patches[p], in));
    tau_[p].swap(previous);
    double sa = 0, s = 0;
    for (std::size_t i = 0; i < tau_[p].size(); ++i) {
      s += area_[p][i] * tau_[p][i].norm();
      sa += area_[p][i];
    }
    mean.push_back(local_->comm.sum(s) / local_->comm.sum(sa));
    // Trapezoidal rule over the interval since the previous sample, its part after start_time
    // (the start value interpolated linearly to start_time). Without the previous sample (a
    // restart from a checkpoint written before it was kept) the interval takes the end value.
    if (!accumulate) continue;
    if (previous.size() != tau_[p].size()) previous = tau_[p];
    if (last_time_ < t0) {
      const double f = (t0 - last_time_) / (t - last_time_);
      for (std::size_t i = 0; i < previous.size(); ++i)
        previous[i] += f * (tau_[p][i] - previous[i]);
    }
    stats_[p].add(previous, tau_[p], elapsed);
    if (support_nodes_)
      for (std::size_t i = 0; i < nodes_[p].size(); ++i)
        if (in_support_[std::size_t(nodes_[p][i])]) support_time_[p][i] += elapsed;
  }
  last_time_ = t;
  sampled_ = true;
  if (history_.is_open()) {
    history_ << fmt::format("{:.17g}", t);
    for (double m : mean) history_ << fmt::format(",{:.9e}", m);
    history_ << '\n' << std::flush;
  }
}

std::vector<io::CheckpointArray> WallShearRecorder::checkpoint_arrays() const {
  const auto patches = static_cast<std::int64_t>(options_.patches.size());
  io::CheckpointArray sums{"wall_shear_sums", local_->global_nodes * patches, wss_cols, {}, {}};
  io::CheckpointArray meta{"wall_shear_meta", patches + 2, 0, {}, {}};
  io::CheckpointArray support{"wall_shear_support_time", local_->global_nodes * patches, 0, {}, {}};
  io::CheckpointArray last{"wall_shear_last_tau", local_->global_nodes * patches, 3, {}, {}};
  for (std::size_t p = 0; p < options_.patches.size(); ++p) {
    const auto s = stats_[p].state();
    const bool empty = s.size() == 1;  // nothing accumulated yet
    for (std::size_t i = 0; i < nodes_[p].size(); ++i) {
      sums.rows.push_back(local_->dual_node[nodes_[p][i]] * patches + std::int64_t(p));
      for (int c = 0; c < wss_cols; ++c)
        sums.data.push_back(empty ? 0.0 : s[wss_cols * i + std::size_t(c)]);
      support.rows.push_back(sums.rows.back());
      support.data.push_back(support_time_[p][i]);
      const Eigen::Vector3d tau = i < tau_[p].size() ? tau_[p][i] : Eigen::Vector3d::Zero();
      last.rows.push_back(sums.rows.back());
      last.data.insert(last.data.end(), tau.data(), tau.data() + 3);
    }
    if (local_->comm.root()) {
      meta.rows.push_back(std::int64_t(p));
      meta.data.push_back(s.back());  // duration
    }
  }
  if (local_->comm.root()) {
    meta.rows.insert(meta.rows.end(), {patches, patches + 1});
    meta.data.insert(meta.data.end(), {last_time_, sampled_ ? 1.0 : 0.0});
  }
  return {sums, meta, support, last};
}

void WallShearRecorder::restore(const io::CheckpointReader& reader) {
  const auto patches = static_cast<std::int64_t>(options_.patches.size());
  if (!reader.has("wall_shear_sums") || !reader.has("wall_shear_meta") ||
      reader.shape("wall_shear_meta").first != patches + 2)
    throw std::runtime_error(
        fmt::format("restart: {} has no wall shear statistics for the {} patch(es) of [wall_shear]",
                    reader.path().string(), patches));
  std::vector<std::int64_t> all(std::size_t(patches + 2));
  for (std::int64_t i = 0; i < patches + 2; ++i) all[std::size_t(i)] = i;
  const auto meta = reader.read_array("wall_shear_meta", all);
  for (std::size_t p = 0; p < options_.patches.size(); ++p) {
    std::vector<std::int64_t> rows;
    for (int node : nodes_[p]) rows.push_back(local_->dual_node[node] * patches + std::int64_t(p));
    auto s = reader.read_array("wall_shear_sums", rows);
    s.push_back(meta[p]);
    if (meta[p] > 0) stats_[p].restore(s);
    // Checkpoints written before the support time was kept: none counted before the restart.
    if (reader.has("wall_shear_support_time"))
      support_time_[p] = reader.read_array("wall_shear_support_time", rows);
    // The last sample's tau_w, the start of the next interval (checkpoints since 2026-12-06).
    tau_[p].clear();
    if (reader.has("wall_shear_last_tau") && meta[std::size_t(patches) + 1] != 0) {
      const auto v = reader.read_array("wall_shear_last_tau", rows);
      for (std::size_t i = 0; i + 2 < v.size(); i += 3)
        tau_[p].emplace_back(v[i], v[i + 1], v[i + 2]);
    }
  }
  last_time_ = meta[std::size_t(patches)];
  sampled_ = meta[std::size_t(patches) + 1] != 0;
  // A restart asked to average from a later start_time than the checkpoint's window began: the
  // window starts afresh (TAWSS over cycles 5-10 from a run that averaged from cycle 1).
  const double duration = stats_.empty() ? 0.0 : stats_.front().duration();
  const double window_start = last_time_ - duration;
  if (duration > 0 && options_.start_time > window_start + 1e-9 * std::max(1.0, last_time_)) {
    for (std::size_t p = 0; p < stats_.size(); ++p) {
      stats_[p] = flow::WallShearStatistics();
      std::fill(support_time_[p].begin(), support_time_[p].end(), 0.0);
    }
    if (local_->comm.root())
      fmt::print(
          "wall_shear: start_time {:.6g} s is later than the checkpoint's averaging window "
          "({:.6g}-{:.6g} s): TAWSS, OSI and RRT start afresh\n",
          options_.start_time, window_start, last_time_);
  }
}

void WallShearRecorder::write(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                              const std::filesystem::path& run_dir) const {
  std::vector<WallNodeRow> mine;
  for (std::size_t p = 0; p < options_.patches.size(); ++p) {
    const auto tawss = stats_[p].tawss(), osi = stats_[p].osi(), rrt = stats_[p].rrt();
    const bool empty = tawss.empty();  // nothing accumulated: no averaging window
    for (std::size_t i = 0; i < nodes_[p].size(); ++i) {
      const int j = nodes_[p][i];
      WallNodeRow r;
      r.patch = int(p);
      r.node = local_->dual_node[j];
      r.x = local_->position[j];
      r.area = area_[p][i];
      r.tawss = empty ? 0.0 : tawss[i];
      r.osi = empty ? 0.0 : osi[i];
      r.rrt = empty ? std::numeric_limits<double>::quiet_NaN() : rrt[i];
      if (i < tau_[p].size()) r.tau = tau_[p][i];
      const double duration = stats_[p].duration();
      r.support = duration > 0 ? support_time_[p][i] / duration : 0.0;
      mine.push_back(r);
    }
  }
  // Surface data is small: gather it on rank 0, so the files are rank-count independent.
  const auto rows = gather_wall_rows(local_->comm, mine);
  if (!local_->comm.root()) return;
  write_wall_shear_csv(run_dir / "wall_shear.csv", options_.patches, rows);
  const double duration = stats_.empty() ? 0.0 : stats_.front().duration();
  const double t0 = last_time_ - duration, t1 = last_time_;
  const auto summaries = summarize_wall_shear(rows, options_.patches.size());
  write_wall_shear_summary(run_dir / "wall_shear_summary.csv", options_.patches, summaries, t0, t1);
  for (std::size_t p = 0; p < summaries.size(); ++p)
    if (duration > 0)
      fmt::print("{}\n", wall_shear_summary_line(options_.patches[p], summaries[p], t0, t1));
    else  // the files hold zeros (and no RRT): say why instead of printing them
      fmt::print(
          "wall_shear {}: no TAWSS, OSI or RRT yet: the run ended at t = {:.6g} s, before the "
          "averaging window opens at wall_shear.start_time = {:.6g} s\n",
          options_.patches[p], last_time_, options_.start_time);
  write_wall_shear_surface(run_dir, mesh, metrics, options_.patches, rows, last_time_);
}

}  // namespace valsalva::analysis
