// Checkpoints: rows by dual-node id, so a state written at one rank count comes back with the
// same bits at any rank count (here the world size and one rank); extra arrays round-trip;
// rotation keeps the newest two; wrong mesh, wrong version and damaged files fail with the file
// named; SIGTERM sets the stop flag on every rank.
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>

#include "io/checkpoint.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "run/stop_signal.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

int world_size() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::path("test_output") / ("checkpoint_np" + std::to_string(world_size())) / name;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return dir;
}

mesh::Mesh box(int n) {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::BoxCellType::mixed;
  spec.cells = {n, 4, 3};
  spec.perturbation = 0.1;
  return mesh::generate_box(spec);
}

// Values with full mantissas, a function of the partition-independent dual id only.
Eigen::Vector3d u_of(std::int64_t id) {
  return {std::sin(0.37 * id) / 3.0, 1.0 / (id + 3.0), std::exp(-1e-3 * id) * M_PI};
}
double p_of(std::int64_t id) {
  return std::cos(1.3 * id) * 1e5 / 7.0;
}

void fill(const mesh::LocalMesh& local, flow::FlowState& state) {
  state.velocity.assign(local.num_local(), Eigen::Vector3d::Constant(NAN));
  state.pressure.assign(local.num_local(), NAN);
  for (int i = 0; i < local.num_owned; ++i) {
    state.velocity[i] = u_of(local.dual_node[i]);
    state.pressure[i] = p_of(local.dual_node[i]);
  }
  state.time = 0.1 / 3.0;
}

int bad_bits(const mesh::LocalMesh& local, const flow::FlowState& state) {
  int bad = 0;
  for (int i = 0; i < local.num_local(); ++i) {  // ghosts included
    bad += state.velocity[i] != u_of(local.dual_node[i]);
    bad += state.pressure[i] != p_of(local.dual_node[i]);
  }
  return bad;
}

}  // namespace

TEST_CASE("checkpoint round trip at the world size and at one rank, bit for bit") {
  const fs::path dir = scratch("roundtrip");
  const auto mesh = box(8);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto hash = io::mesh_hash(mesh);
  auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  flow::FlowState state;
  fill(local, state);

  // Extra array: 10 rows x 2 cols, rows dealt round-robin over ranks.
  io::CheckpointArray extra{"stats_sums", 10, 2, {}, {}};
  for (std::int64_t r = local.comm.rank(); r < 10; r += local.comm.size()) {
    extra.rows.push_back(r);
    extra.data.push_back(r / 3.0);
    extra.data.push_back(-r * M_PI);
  }
  io::CheckpointWriter writer(local, hash, dir);
  for (std::int64_t step : {5, 10, 15}) {
    state.time = step * 1e-3 / 3.0;
    writer.write(state, step, 1e-3 / 3.0, std::span<const io::CheckpointArray>(&extra, 1));
  }
  // Rotation keeps the newest two; no temporary file is left.
  CHECK_FALSE(fs::exists(writer.path_of(5)));
  CHECK(fs::exists(writer.path_of(10)));
  CHECK_FALSE(fs::exists(writer.path_of(15).string() + ".tmp"));
  const auto latest = io::latest_checkpoint(dir);
  REQUIRE(latest.has_value());
  CHECK(*latest == writer.path_of(15));

  // Same rank count.
  {
    io::CheckpointReader reader(local, hash, *latest);
    flow::FlowState back;
    reader.read_state(back);
    CHECK(reader.info().step == 15);
    CHECK(reader.info().dt == 1e-3 / 3.0);
    CHECK(back.time == 15 * 1e-3 / 3.0);
    CHECK(local.comm.sum(std::int64_t(bad_bits(local, back))) == 0);
    CHECK(reader.shape("stats_sums") == std::pair<std::int64_t, int>{10, 2});
    const std::vector<std::int64_t> rows = {9, 0, 4};
    const auto data = reader.read_array("stats_sums", rows);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      CHECK(data[2 * i] == rows[i] / 3.0);
      CHECK(data[2 * i + 1] == -rows[i] * M_PI);
    }
    CHECK_THROWS_WITH(reader.read_array("stats_other", rows),
                      doctest::Contains("no array 'stats_other'"));
  }
  // One rank (each rank alone on its own communicator), another partition: same bits.
  {
    auto single = mesh::distribute(mesh, metrics, MPI_COMM_SELF, {2, mesh::PartitionMethod::metis});
    io::CheckpointReader reader(single, hash, *latest);
    flow::FlowState back;
    reader.read_state(back);
    CHECK(single.num_owned == metrics.num_nodes());
    CHECK(bad_bits(single, back) == 0);
  }
}

TEST_CASE("checkpoint errors name the file and the mismatch") {
  const fs::path dir = scratch("errors");
  const auto mesh = box(8);
  const auto metrics = mesh::compute_dual_metrics(mesh);
  auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  flow::FlowState state;
  fill(local, state);
  io::CheckpointWriter writer(local, io::mesh_hash(mesh), dir);
  const auto path = writer.write(state, 3, 1e-3);

  // Another mesh: different node count.
  const auto other = box(9);
  const auto other_metrics = mesh::compute_dual_metrics(other);
  auto other_local =
      mesh::distribute(other, other_metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  CHECK_THROWS_WITH(io::CheckpointReader(other_local, io::mesh_hash(other), path),
                    doctest::Contains("was written for another mesh"));
  // Same node count, moved nodes: the hash differs.
  auto moved = mesh;
  moved.nodes[7].x() += 1e-9;
  CHECK(io::mesh_hash(moved) != io::mesh_hash(mesh));
  CHECK_THROWS_WITH(io::CheckpointReader(local, io::mesh_hash(moved), path),
                    doctest::Contains(path.c_str()));

  // Damaged files: garbage and a truncated copy.
  const fs::path garbage = dir / "checkpoint_000000009.h5";
  const fs::path truncated = dir / "truncated.h5";
  if (local.comm.root()) {
    std::ofstream(garbage) << "not an HDF5 file\n";
    const auto size = fs::file_size(path);
    fs::copy_file(path, truncated);
    fs::resize_file(truncated, size / 2);
  }
  local.comm.barrier();
  CHECK_THROWS_WITH(io::CheckpointReader(local, io::mesh_hash(mesh), garbage),
                    doctest::Contains(garbage.c_str()));
  CHECK_THROWS_WITH(io::CheckpointReader(local, io::mesh_hash(mesh), truncated),
                    doctest::Contains(truncated.c_str()));
  CHECK_THROWS_WITH(io::CheckpointReader(local, io::mesh_hash(mesh), dir / "none.h5"),
                    doctest::Contains("no such file"));

  // Another format version.
  const fs::path future = dir / "future.h5";
  {
    io::h5::File file(MPI_COMM_WORLD, future, io::h5::Mode::create);
    file.write_attribute("format_version", 99);
    file.close();
  }
  CHECK_THROWS_WITH(io::CheckpointReader(local, io::mesh_hash(mesh), future),
                    doctest::Contains("format version 99"));
}

TEST_CASE("SIGTERM on one rank stops every rank") {
  run::StopSignal stop;
  CHECK_FALSE(stop.requested(MPI_COMM_WORLD));
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::raise(SIGTERM);
  CHECK(run::StopSignal::raised_locally() == (rank == 0));
  CHECK(stop.requested(MPI_COMM_WORLD));
  if (rank == 0) CHECK(run::StopSignal::signal_number() == SIGTERM);
  run::StopSignal::clear();
  CHECK_FALSE(stop.requested(MPI_COMM_WORLD));
}
