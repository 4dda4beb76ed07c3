#include "analysis/phase_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <stdexcept>

#include "core/comm.hpp"
#include "io/field_output.hpp"
#include "mesh/plane_cut.hpp"

namespace valsalva::analysis {

namespace {

// All ranks' ids, sorted (every rank gets the same list).
std::vector<std::int64_t> gather_sorted(const core::Comm& comm,
                                        const std::vector<std::int64_t>& mine) {
  auto all = comm.all_gather(mine);
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

PhaseStatistics::PhaseStatistics(const mesh::LocalMesh& local, PhaseStatisticsOptions options,
                                 std::vector<int> nodes)
    : PhaseAccumulator(std::move(options), nodes.size()), local_(&local), nodes_(std::move(nodes)) {
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
  sample_.resize(nodes_.size() * 4);
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

void PhaseStatistics::merge(const PhaseStatistics& other) {
  if (other.nodes_ != nodes_)
    throw std::invalid_argument("statistics: merge of accumulators over other nodes or bins");
  PhaseAccumulator::merge(other);
}

std::vector<io::CheckpointArray> PhaseStatistics::checkpoint_arrays() const {
  auto arrays = moment_arrays(rows_, global_rows_, local_->comm.root());
  io::CheckpointArray nodes{options_.name + "_nodes", global_rows_, 0, rows_, {}};
  for (int i : nodes_) nodes.data.push_back(double(local_->dual_node[i]));
  arrays.push_back(std::move(nodes));
  return arrays;
}

void PhaseStatistics::restore(const io::CheckpointReader& reader) {
  const std::string where =
      fmt::format("checkpoint '{}', statistics '{}'", reader.path().string(), options_.name);
  restore_moments(reader, rows_, global_rows_, where);
  const auto ids = reader.read_array(options_.name + "_nodes", rows_);
  int wrong = 0;
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    wrong += ids[i] != double(local_->dual_node[nodes_[i]]);
  if (local_->comm.sum(std::int64_t(wrong)) != 0)
    throw std::runtime_error(fmt::format("{}: the covered nodes differ", where));
}

std::filesystem::path PhaseStatistics::write(const mesh::Mesh& mesh,
                                             const mesh::DualMetrics& metrics,
                                             const std::filesystem::path& dir) const {
  const auto& local = *local_;
  if (local.comm.root()) std::filesystem::create_directories(dir);
  local.comm.barrier();
  io::FieldOutput out(mesh, metrics, local, dir, options_.name);
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

std::vector<int> all_owned_nodes(const mesh::LocalMesh& local) {
  std::vector<int> v(local.num_owned);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

std::vector<int> nodes_near_plane(const mesh::LocalMesh& local, const Eigen::Vector3d& point,
                                  const Eigen::Vector3d& normal, double half_thickness) {
  const Eigen::Vector3d n = normal.normalized();
  std::vector<int> v;
  for (int i = 0; i < local.num_owned; ++i)
    if (std::abs((local.position[i] - point).dot(n)) <= half_thickness) v.push_back(i);
  return v;
}

std::vector<int> nodes_in_box(const mesh::LocalMesh& local, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi) {
  std::vector<int> v;
  for (int i = 0; i < local.num_owned; ++i)
    if ((local.position[i].array() >= lo.array()).all() &&
        (local.position[i].array() <= hi.array()).all())
      v.push_back(i);
  return v;
}

std::vector<int> nodes_of_cut_cells(const mesh::LocalMesh& local, const mesh::Mesh& mesh,
                                    const mesh::DualMetrics& metrics, const Eigen::Vector3d& point,
                                    const Eigen::Vector3d& normal, const Eigen::Vector3d& lo,
                                    const Eigen::Vector3d& hi) {
  std::vector<char> marked(metrics.mesh_node_of_dual.size(), 0);
  for (const mesh::GlobalIndex c : mesh::cells_cut_by_plane(mesh, point, normal, lo, hi))
    for (const mesh::GlobalIndex node : mesh.cell(c))
      marked[static_cast<std::size_t>(metrics.dual_of_mesh_node[static_cast<std::size_t>(node)])] =
          1;
  std::vector<int> v;
  for (int i = 0; i < local.num_owned; ++i)
    if (marked[static_cast<std::size_t>(local.dual_node[i])]) v.push_back(i);
  return v;
}

}  // namespace valsalva::analysis
