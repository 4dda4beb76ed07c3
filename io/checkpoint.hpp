// Checkpoint/restart of a distributed flow state in parallel HDF5. Rows are dual-node ids
// (LocalMesh::dual_node, the partition-independent numbering of the replicated DualMetrics), so a
// checkpoint written at one rank count is read at any other; values are stored as raw doubles,
// so a restart at the same rank count continues bit for bit.
//
// File <dir>/<basename>_<step, 9 digits>.h5:
//   attributes  format_version, time, step, dt, global_nodes, mesh_hash_hi, mesh_hash_lo, and
//               checksum_<dataset>_hi/_lo of every dataset (verified on every read)
//   datasets    velocity [N x 3], pressure [N], and the extra arrays (any name, own row count)
// Writing goes to "<file>.tmp", closed, then renamed by rank 0, so a crash mid-write never
// leaves a truncated file under the final name; afterwards only the newest `keep` are kept.
//
// How the run loop uses it:
//   const auto hash = io::mesh_hash(mesh);                       // once, on every rank
//   io::CheckpointWriter ckpt(local, hash, run_dir / "checkpoints");
//   ... every N steps, every M wall-clock minutes, or when io::StopSignal::requested(comm):
//   ckpt.write(state, step, dt, stats.checkpoint_arrays());   // collective
//   restart:  auto path = io::latest_checkpoint(run_dir / "checkpoints");
//             io::CheckpointReader in(local, hash, path);      // throws on mismatch
//             in.read_state(state); step = in.info().step; dt = in.info().dt;
//             stats.restore(in);                               // extra arrays
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "flow/projection_rk4.hpp"
#include "io/hdf5_file.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::io {

// Version 2: every dataset carries a checksum, verified when it is read.
inline constexpr int checkpoint_format_version = 2;

// 64-bit hash of node coordinates (bit patterns), cell types and connectivity: identifies the
// mesh a checkpoint belongs to independently of the partition. Same value on every rank.
std::uint64_t mesh_hash(const mesh::Mesh& mesh);

// A named array saved with the state: `rows` are this rank's global row ids (unique over ranks)
// in a numbering of the caller's choice with `global_rows` rows; `cols` == 0 means 1-D.
struct CheckpointArray {
  std::string name;  // [A-Za-z0-9_]+, not "velocity" or "pressure"
  std::int64_t global_rows = 0;
  int cols = 0;
  std::vector<std::int64_t> rows;
  std::vector<double> data;  // rows.size() * max(cols, 1), row-major
};

struct CheckpointInfo {
  int format_version = 0;
  double time = 0;
  std::int64_t step = 0;
  double dt = 0;  // the last step's time step
  std::int64_t global_nodes = 0;
  std::uint64_t mesh_hash = 0;
};

class CheckpointWriter {
 public:
  CheckpointWriter(const mesh::LocalMesh& local, std::uint64_t mesh_hash, std::filesystem::path dir,
                   std::string basename = "checkpoint", int keep = 2);

  // Collective. Writes the owned nodes' velocity and pressure and the extra arrays; returns the
  // final path. Older checkpoints beyond the newest `keep` of this basename are removed.
  std::filesystem::path write(const flow::FlowState& state, std::int64_t step, double dt,
                              std::span<const CheckpointArray> extras = {});

  std::filesystem::path path_of(std::int64_t step) const;

 private:
  const mesh::LocalMesh* local_;
  std::uint64_t hash_;
  std::filesystem::path dir_;
  std::string basename_;
  int keep_;
  std::vector<std::int64_t> owned_rows_;
};

// A nodal field (owned values of `field`, local order) as an extra array `name` with rows by
// dual node, and its inverse: every local node's value (owned and ghosts) of that array.
CheckpointArray nodal_checkpoint_array(const std::string& name, const mesh::LocalMesh& local,
                                       const flow::ScalarField& field);
class CheckpointReader;
flow::ScalarField read_nodal_array(const CheckpointReader& reader, const mesh::LocalMesh& local,
                                   const std::string& name);

// An edge field (one value per local edge, LocalMesh::edges orientation, e.g. the face flux of
// flow::ProjectionRK4) as an extra array with rows by global edge (DualMetrics::edges, its
// orientation), each edge written by the rank owning its first node; and its inverse: every
// local edge's value. Collective.
CheckpointArray edge_checkpoint_array(const std::string& name, const mesh::LocalMesh& local,
                                      const std::vector<double>& field);
std::vector<double> read_edge_array(const CheckpointReader& reader, const mesh::LocalMesh& local,
                                    const std::string& name);

// A small array that every rank holds alike (e.g. the lumped outlets' states), written by rank 0
// as one 1-D row per value, and its inverse (every rank reads all of it).
CheckpointArray replicated_checkpoint_array(const std::string& name, const mesh::LocalMesh& local,
                                            const std::vector<double>& values);
std::vector<double> read_replicated_array(const CheckpointReader& reader, const std::string& name);

// Newest complete checkpoint <basename>_<step>.h5 in `dir` (highest step), or nullopt.
std::optional<std::filesystem::path> latest_checkpoint(const std::filesystem::path& dir,
                                                       const std::string& basename = "checkpoint");

class CheckpointReader {
 public:
  // Collective. Throws std::runtime_error naming the file when it cannot be opened, has another
  // format version, or was written for another mesh (node count or hash differ).
  CheckpointReader(const mesh::LocalMesh& local, std::uint64_t mesh_hash,
                   std::filesystem::path path);

  const CheckpointInfo& info() const { return info_; }
  const std::filesystem::path& path() const { return file_.path(); }

  // Collective. Fills velocity and pressure of every local node (owned and ghosts: ghosts get
  // their owner's stored value, as a halo exchange would) and the time.
  void read_state(flow::FlowState& state) const;

  bool has(const std::string& name) const { return file_.has(name); }
  // {global_rows, cols} of an extra array (cols 0 for 1-D); throws naming file and array if absent.
  std::pair<std::int64_t, int> shape(const std::string& name) const;
  // Collective. Rows `rows` of extra array `name`, row-major.
  std::vector<double> read_array(const std::string& name, std::span<const std::int64_t> rows) const;

 private:
  const mesh::LocalMesh* local_;
  h5::File file_;
  CheckpointInfo info_;
};

}  // namespace valsalva::io
