#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <regex>
#include <stdexcept>

namespace valsalva::io {

namespace {

// FNV-1a over 64-bit words (one multiply per word keeps hashing a 3 M-node mesh fast).
struct Hasher {
  std::uint64_t h = 14695981039346656037ull;
  void add(std::uint64_t word) {
    h ^= word;
    h *= 1099511628211ull;
  }
  void add(double x) {
    std::uint64_t w = 0;
    std::memcpy(&w, &x, sizeof w);
    add(w);
  }
};

double hi(std::uint64_t h) {
  return static_cast<double>(h >> 32);
}
double lo(std::uint64_t h) {
  return static_cast<double>(h & 0xffffffffull);
}

std::string hex(std::uint64_t h) {
  return fmt::format("{:016x}", h);
}

// Collective: rank 0 runs `action`; its error, if any, is raised on every rank.
template <class F>
void on_root(const core::Comm& comm, F&& action) {
  std::string error;
  if (comm.root()) {
    try {
      action();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  h5::settle(comm.get(), error);
}

// Checksums of datasets (attributes checksum_<name>_hi/_lo): the sum modulo 2^64 of one FNV-1a
// hash per row (row id, then its values' bits), so it does not depend on which rank holds a row.
// All-zero rows add nothing: rows no rank writes (sparse arrays) read back as zeros.
std::uint64_t row_checksum(std::span<const std::int64_t> rows, std::span<const double> data,
                           int cols) {
  const std::size_t width = static_cast<std::size_t>(std::max(cols, 1));
  std::uint64_t sum = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    Hasher row;
    row.add(static_cast<std::uint64_t>(rows[r]));
    bool zero = true;
    for (std::size_t c = 0; c < width; ++c) {
      row.add(data[r * width + c]);
      zero = zero && std::bit_cast<std::uint64_t>(data[r * width + c]) == 0;
    }
    if (!zero) sum += row.h;
  }
  return sum;
}

std::uint64_t global_checksum(const core::Comm& comm, std::uint64_t local) {
  std::uint64_t total = 0;
  if (MPI_Allreduce(&local, &total, 1, MPI_UINT64_T, MPI_SUM, comm.get()) != MPI_SUCCESS)
    throw std::runtime_error("checkpoint: MPI_Allreduce of a checksum failed");
  return total;
}

void write_checksum(h5::File& file, const core::Comm& comm, const std::string& name,
                    std::span<const std::int64_t> rows, std::span<const double> data, int cols) {
  const std::uint64_t sum = global_checksum(comm, row_checksum(rows, data, cols));
  file.write_attribute("checksum_" + name + "_hi", hi(sum));
  file.write_attribute("checksum_" + name + "_lo", lo(sum));
}

// Collective: every rank hashes one contiguous block of rows; throws naming file and dataset
// when the data no longer match the checksum written with them.
void verify_checksum(const h5::File& file, const core::Comm& comm, const std::string& name) {
  const auto dims = file.dims(name);
  const std::int64_t n = dims.at(0);
  const int cols = dims.size() > 1 ? static_cast<int>(dims[1]) : 0;
  const std::int64_t first = n * comm.rank() / comm.size(),
                     end = n * (comm.rank() + 1) / comm.size();
  std::vector<std::int64_t> rows(static_cast<std::size_t>(end - first));
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = first + static_cast<std::int64_t>(i);
  const auto data = file.read_rows<double>(name, rows);
  const std::uint64_t sum = global_checksum(comm, row_checksum(rows, data, cols));
  const std::uint64_t stored =
      (static_cast<std::uint64_t>(file.read_attribute("checksum_" + name + "_hi")) << 32) |
      static_cast<std::uint64_t>(file.read_attribute("checksum_" + name + "_lo"));
  if (sum != stored)
    throw std::runtime_error(fmt::format(
        "checkpoint '{}': dataset '{}' does not match its checksum (stored {}, computed {}): the "
        "file was altered or damaged after it was written; restart from an older checkpoint",
        file.path().string(), name, hex(stored), hex(sum)));
}

}  // namespace

std::uint64_t mesh_hash(const mesh::Mesh& mesh) {
  Hasher hash;
  hash.add(static_cast<std::uint64_t>(mesh.num_nodes()));
  for (const auto& x : mesh.nodes)
    for (int c = 0; c < 3; ++c) hash.add(x[c]);
  hash.add(static_cast<std::uint64_t>(mesh.num_cells()));
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    hash.add(static_cast<std::uint64_t>(mesh.cell_types[c]));
    for (auto n : mesh.cell(c)) hash.add(static_cast<std::uint64_t>(n));
  }
  return hash.h;
}

CheckpointWriter::CheckpointWriter(const mesh::LocalMesh& local, std::uint64_t mesh_hash,
                                   std::filesystem::path dir, std::string basename, int keep)
    : local_(&local),
      hash_(mesh_hash),
      dir_(std::move(dir)),
      basename_(std::move(basename)),
      keep_(keep) {
  if (keep_ < 1) throw std::invalid_argument(fmt::format("checkpoint: keep = {} < 1", keep_));
  owned_rows_.assign(local.dual_node.begin(), local.dual_node.begin() + local.num_owned);
  on_root(local.comm, [&] { std::filesystem::create_directories(dir_); });
}

std::filesystem::path CheckpointWriter::path_of(std::int64_t step) const {
  return dir_ / fmt::format("{}_{:09d}.h5", basename_, step);
}

std::filesystem::path CheckpointWriter::write(const flow::FlowState& state, std::int64_t step,
                                              double dt, std::span<const CheckpointArray> extras) {
  const mesh::LocalMesh& local = *local_;
  const auto final_path = path_of(step);
  auto tmp_path = final_path;
  tmp_path += ".tmp";
  {
    h5::File file(local.comm.get(), tmp_path, h5::Mode::create);
    file.write_attribute("format_version", checkpoint_format_version);
    file.write_attribute("time", state.time);
    file.write_attribute("step", static_cast<double>(step));
    file.write_attribute("dt", dt);
    file.write_attribute("global_nodes", static_cast<double>(local.global_nodes));
    file.write_attribute("mesh_hash_hi", hi(hash_));
    file.write_attribute("mesh_hash_lo", lo(hash_));
    const auto n = static_cast<std::size_t>(local.num_owned);
    const std::span<const double> velocity(state.velocity.data()->data(), 3 * n);
    const std::span<const double> pressure(state.pressure.data(), n);
    file.write_rows<double>("velocity", local.global_nodes, 3, owned_rows_, velocity);
    file.write_rows<double>("pressure", local.global_nodes, 0, owned_rows_, pressure);
    write_checksum(file, local.comm, "velocity", owned_rows_, velocity, 3);
    write_checksum(file, local.comm, "pressure", owned_rows_, pressure, 0);
    for (const auto& a : extras) {
      if (a.name == "velocity" || a.name == "pressure" ||
          !std::regex_match(a.name, std::regex("[A-Za-z0-9_]+")))
        throw std::invalid_argument(
            fmt::format("checkpoint '{}': bad extra array name '{}'", tmp_path.string(), a.name));
      file.write_rows<double>(a.name, a.global_rows, a.cols, a.rows, a.data);
      write_checksum(file, local.comm, a.name, a.rows, a.data, a.cols);
    }
    file.close();
  }
  on_root(local.comm, [&] {
    std::filesystem::rename(tmp_path, final_path);
    // Rotation: keep the newest `keep_` complete checkpoints of this basename.
    const std::regex pattern(basename_ + "_([0-9]{9})\\.h5");
    std::vector<std::pair<std::int64_t, std::filesystem::path>> found;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
      std::smatch m;
      const std::string name = entry.path().filename().string();
      if (std::regex_match(name, m, pattern)) found.emplace_back(std::stoll(m[1]), entry.path());
    }
    std::sort(found.begin(), found.end());
    for (std::size_t i = 0; i + keep_ < found.size(); ++i) std::filesystem::remove(found[i].second);
  });
  return final_path;
}

CheckpointArray nodal_checkpoint_array(const std::string& name, const mesh::LocalMesh& local,
                                       const flow::ScalarField& field) {
  if (field.size() < static_cast<std::size_t>(local.num_owned))
    throw std::invalid_argument(
        fmt::format("nodal_checkpoint_array {}: {} values for {} owned nodes", name, field.size(),
                    local.num_owned));
  CheckpointArray a{name, local.global_nodes, 0, {}, {}};
  for (int i = 0; i < local.num_owned; ++i) {
    a.rows.push_back(local.dual_node[i]);
    a.data.push_back(field[i]);
  }
  return a;
}

flow::ScalarField read_nodal_array(const CheckpointReader& reader, const mesh::LocalMesh& local,
                                   const std::string& name) {
  const std::vector<std::int64_t> rows(local.dual_node.begin(), local.dual_node.end());
  return reader.read_array(name, rows);
}

CheckpointArray replicated_checkpoint_array(const std::string& name, const mesh::LocalMesh& local,
                                            const std::vector<double>& values) {
  CheckpointArray a{name, static_cast<std::int64_t>(values.size()), 0, {}, {}};
  if (local.comm.root())
    for (std::size_t r = 0; r < values.size(); ++r)
      a.rows.push_back(static_cast<std::int64_t>(r)), a.data.push_back(values[r]);
  return a;
}

std::vector<double> read_replicated_array(const CheckpointReader& reader, const std::string& name) {
  const auto rows = reader.shape(name).first;
  std::vector<std::int64_t> all(static_cast<std::size_t>(rows));
  for (std::int64_t r = 0; r < rows; ++r) all[static_cast<std::size_t>(r)] = r;
  return reader.read_array(name, all);
}

CheckpointArray edge_checkpoint_array(const std::string& name, const mesh::LocalMesh& local,
                                      const std::vector<double>& field) {
  if (field.size() != local.edges.size())
    throw std::invalid_argument(
        fmt::format("edge_checkpoint_array {}: {} values for {} local edges", name, field.size(),
                    local.edges.size()));
  std::int64_t count = 0;
  for (const auto e : local.global_edge) count = std::max<std::int64_t>(count, e + 1);
  CheckpointArray a{name, local.comm.max(count), 0, {}, {}};
  for (std::size_t e = 0; e < local.edges.size(); ++e) {
    const bool flipped = local.edge_flipped[e] != 0;
    const int first = flipped ? local.edges[e][1] : local.edges[e][0];
    if (first >= local.num_owned) continue;
    a.rows.push_back(local.global_edge[e]);
    a.data.push_back(flipped ? -field[e] : field[e]);
  }
  return a;
}

std::vector<double> read_edge_array(const CheckpointReader& reader, const mesh::LocalMesh& local,
                                    const std::string& name) {
  const std::vector<std::int64_t> rows(local.global_edge.begin(), local.global_edge.end());
  std::vector<double> values = reader.read_array(name, rows);
  for (std::size_t e = 0; e < values.size(); ++e)
    if (local.edge_flipped[e] != 0) values[e] = -values[e];
  return values;
}

std::optional<std::filesystem::path> latest_checkpoint(const std::filesystem::path& dir,
                                                       const std::string& basename) {
  if (!std::filesystem::is_directory(dir)) return std::nullopt;
  const std::regex pattern(basename + "_([0-9]{9})\\.h5");
  std::optional<std::filesystem::path> best;
  std::int64_t best_step = -1;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (!std::regex_match(name, m, pattern)) continue;
    const std::int64_t step = std::stoll(m[1]);
    if (step > best_step) best_step = step, best = entry.path();
  }
  return best;
}

CheckpointReader::CheckpointReader(const mesh::LocalMesh& local, std::uint64_t mesh_hash,
                                   std::filesystem::path path)
    : local_(&local), file_(local.comm.get(), std::move(path), h5::Mode::read) {
  const std::string where = fmt::format("checkpoint '{}'", file_.path().string());
  info_.format_version = static_cast<int>(file_.read_attribute("format_version"));
  if (info_.format_version != checkpoint_format_version)
    throw std::runtime_error(fmt::format("{}: format version {}, this program reads version {}",
                                         where, info_.format_version, checkpoint_format_version));
  info_.time = file_.read_attribute("time");
  info_.step = static_cast<std::int64_t>(file_.read_attribute("step"));
  info_.dt = file_.read_attribute("dt");
  info_.global_nodes = static_cast<std::int64_t>(file_.read_attribute("global_nodes"));
  info_.mesh_hash = (static_cast<std::uint64_t>(file_.read_attribute("mesh_hash_hi")) << 32) |
                    static_cast<std::uint64_t>(file_.read_attribute("mesh_hash_lo"));
  if (info_.global_nodes != local.global_nodes || info_.mesh_hash != mesh_hash)
    throw std::runtime_error(fmt::format(
        "{} was written for another mesh: {} nodes, mesh hash {}; this run's mesh has {} nodes, "
        "mesh hash {}",
        where, info_.global_nodes, hex(info_.mesh_hash), local.global_nodes, hex(mesh_hash)));
  for (const char* name : {"velocity", "pressure"}) {
    const auto dims = file_.dims(name);
    if (dims.empty() || dims[0] != local.global_nodes)
      throw std::runtime_error(fmt::format("{}: dataset '{}' has {} rows, expected {}", where, name,
                                           dims.empty() ? 0 : dims[0], local.global_nodes));
  }
}

void CheckpointReader::read_state(flow::FlowState& state) const {
  const mesh::LocalMesh& local = *local_;
  const std::span<const std::int64_t> rows(local.dual_node.data(), local.dual_node.size());
  verify_checksum(file_, local.comm, "velocity");
  verify_checksum(file_, local.comm, "pressure");
  const auto v = file_.read_rows<double>("velocity", rows);
  state.pressure = file_.read_rows<double>("pressure", rows);
  state.velocity.resize(local.num_local());
  for (int i = 0; i < local.num_local(); ++i)
    state.velocity[i] = Eigen::Vector3d(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  state.time = info_.time;
  // A state that is not finite is no state to continue (the run would stop at once and blame
  // the flow): refused naming the file.
  int bad = -1;
  for (int i = 0; i < local.num_owned && bad < 0; ++i)
    if (!state.velocity[i].allFinite() || !std::isfinite(state.pressure[i])) bad = i;
  const std::int64_t first =
      local.comm.max(bad >= 0 ? static_cast<std::int64_t>(local.dual_node[bad]) : std::int64_t(-1));
  if (first >= 0)
    throw std::runtime_error(fmt::format(
        "checkpoint '{}': the state is not finite (velocity or pressure of node {} is NaN or "
        "inf); restart from an older checkpoint",
        file_.path().string(), first));
}

std::pair<std::int64_t, int> CheckpointReader::shape(const std::string& name) const {
  if (!file_.has(name))
    throw std::runtime_error(
        fmt::format("checkpoint '{}': no array '{}'", file_.path().string(), name));
  const auto dims = file_.dims(name);
  return {dims.at(0), dims.size() > 1 ? static_cast<int>(dims[1]) : 0};
}

std::vector<double> CheckpointReader::read_array(const std::string& name,
                                                 std::span<const std::int64_t> rows) const {
  shape(name);
  verify_checksum(file_, local_->comm, name);
  return file_.read_rows<double>(name, rows);
}

}  // namespace valsalva::io
