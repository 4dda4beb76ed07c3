// Phase statistics: a synthetic periodic signal with known phase means, RMS and Reynolds
// stresses (cycle-to-cycle fluctuations from exactly zero-mean, orthogonal +-1 sequences);
// a 1e8 offset with 1e-3 fluctuations (Welford keeps 1e-6 relative, the naive sum of squares
// loses everything); Chan merge equals the sequential accumulation; checkpoint round trip at
// the world size and at one rank; HDF5/XDMF output read back.
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>
#include <filesystem>

#include "analysis/phase_statistics.hpp"
#include "core/comm.hpp"
#include "io/xdmf_writer.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/plane_cut.hpp"
#include "mesh/point_locator.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

constexpr double period = 0.8, rho = 1100;
constexpr int bins = 4, cycles = 8;

mesh::Mesh box() {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::BoxCellType::tetra;
  spec.cells = {6, 4, 3};
  return mesh::generate_box(spec);
}

// Zero-mean, unit-variance, mutually orthogonal sequences over 8 cycles (Walsh functions).
double e(std::int64_t c) {
  return c % 2 ? -1.0 : 1.0;
}
double f(std::int64_t c) {
  return (c / 2) % 2 ? -1.0 : 1.0;
}
double g(std::int64_t c) {
  return (c / 4) % 2 ? -1.0 : 1.0;
}

// Phase mean of u at node position x in bin b.
double mean_u(const Eigen::Vector3d& x, int b) {
  return x.x() + std::sin(2 * M_PI * (b + 0.5) / bins);
}

// Sample at one node, cycle c, bin b: mean + a e + 0.5 a f (v), ...
void fill(const mesh::LocalMesh& local, std::int64_t c, int b, flow::FlowState& s) {
  s.velocity.resize(local.num_local());
  s.pressure.resize(local.num_local());
  for (int i = 0; i < local.num_owned; ++i) {
    const auto& x = local.position[i];
    const double a = 0.1 * (1 + x.y());
    s.velocity[i] = {mean_u(x, b) + a * e(c), -0.5 + 0.5 * a * e(c) + a * f(c), 2 * a * g(c)};
    s.pressure[i] = 100.0 * b + 3 * a * f(c);
  }
}

void run_cycles(const mesh::LocalMesh& local, analysis::PhaseStatistics& stats, int first,
                int last) {
  flow::FlowState s;
  for (int c = first; c < last; ++c)
    for (int b = 0; b < bins; ++b) {
      fill(local, c, b, s);
      stats.add(0.2 + (c + (b + 0.5) / bins) * period, s.velocity, s.pressure);
    }
}

}  // namespace

TEST_CASE("phase statistics of a synthetic periodic signal") {
  const auto mesh = box();
  const auto metrics = mesh::compute_dual_metrics(mesh);
  auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  analysis::PhaseStatistics stats(local, {period, bins, 0.2, rho, "phase"},
                                  analysis::all_owned_nodes(local));
  CHECK(stats.bin_of(0.2) == 0);
  CHECK(stats.bin_of(0.2 + 0.25 * period) == 1);
  CHECK(stats.bin_of(0.2 + 3.99 * period) == 3);
  CHECK(stats.cycle_of(0.2 + 2.5 * period) == 2);
  flow::FlowState before;
  fill(local, 0, 0, before);
  stats.add(0.1, before.velocity, before.pressure);  // before start: ignored
  run_cycles(local, stats, 0, cycles);
  CHECK(stats.cycles() == cycles);
  double worst = 0;
  for (int b = 0; b < bins; ++b) {
    CHECK(stats.count(b) == cycles);
    for (std::size_t i = 0; i < stats.nodes().size(); ++i) {
      const auto& x = local.position[stats.nodes()[i]];
      const double a = 0.1 * (1 + x.y());
      const int n = int(i);
      worst = std::max(
          {worst, std::abs(stats.mean(b, n, 0) - mean_u(x, b)), std::abs(stats.mean(b, n, 1) + 0.5),
           std::abs(stats.mean(b, n, 3) - 100.0 * b), std::abs(stats.rms(b, n, 0) - a),
           std::abs(stats.rms(b, n, 1) - a * std::sqrt(1.25)), std::abs(stats.rms(b, n, 2) - 2 * a),
           std::abs(stats.rms(b, n, 3) - 3 * a),
           std::abs(stats.reynolds_stress(b, n, 0, 1) - 0.5 * a * a),
           std::abs(stats.reynolds_stress(b, n, 1, 0) - 0.5 * a * a),
           std::abs(stats.reynolds_stress(b, n, 0, 2)), std::abs(stats.reynolds_stress(b, n, 2, 1)),
           std::abs(stats.kinetic_energy(b, n) - rho / 2 * a * a * (1 + 1.25 + 4)) / rho});
    }
  }
  CHECK(local.comm.max(worst) < 1e-12);  // a few ulps of the largest value, p = 300 Pa

  // Chan merge: cycles 0-2 and 3-7 accumulated apart, then merged.
  analysis::PhaseStatistics first(local, stats.options(), stats.nodes());
  analysis::PhaseStatistics second(local, stats.options(), stats.nodes());
  run_cycles(local, first, 0, 3);
  run_cycles(local, second, 3, cycles);
  first.merge(second);
  CHECK(first.cycles() == cycles);
  double merge_error = 0;
  for (int b = 0; b < bins; ++b)
    for (int i = 0; i < int(stats.nodes().size()); ++i)
      for (int q = 0; q < 4; ++q)
        merge_error = std::max({merge_error, std::abs(first.mean(b, i, q) - stats.mean(b, i, q)),
                                std::abs(first.rms(b, i, q) - stats.rms(b, i, q))});
  CHECK(local.comm.max(merge_error) < 1e-12);
}

TEST_CASE("phase statistics: large offset, Welford against the naive sum of squares") {
  const auto mesh = box();
  const auto metrics = mesh::compute_dual_metrics(mesh);
  auto local = mesh::distribute(mesh, metrics, MPI_COMM_SELF, {2, mesh::PartitionMethod::metis});
  analysis::PhaseStatistics stats(local, {0.0, 1, 0.0, rho, "mean"}, {0});
  const double offset = 1e8, sigma = 1e-3;
  double sum = 0, sum2 = 0;
  std::vector<double> sample(4, 0.0);
  const int n = 1000;
  for (int k = 0; k < n; ++k) {
    sample[0] = offset + sigma * e(k) + 0.3 * sigma * std::sin(0.1 * k);
    sum += sample[0], sum2 += sample[0] * sample[0];
    stats.add_sample(0, 0, sample);
  }
  // Reference: two passes in long double over the same stored doubles.
  long double mean = 0, var = 0;
  for (int k = 0; k < n; ++k)
    mean += (long double)(offset + sigma * e(k) + 0.3 * sigma * std::sin(0.1 * k));
  mean /= n;
  for (int k = 0; k < n; ++k) {
    const long double d =
        (long double)(offset + sigma * e(k) + 0.3 * sigma * std::sin(0.1 * k)) - mean;
    var += d * d;
  }
  const double rms_ref = std::sqrt(double(var / n));
  const double naive = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
  MESSAGE("rms reference ", rms_ref, ", Welford ", stats.rms(0, 0, 0), ", naive ", naive);
  CHECK(std::abs(stats.rms(0, 0, 0) - rms_ref) < 1e-6 * rms_ref);
  CHECK(std::abs(naive - rms_ref) > 0.5 * rms_ref);  // the naive formula is useless here
}

TEST_CASE("phase statistics: checkpoint round trip and output") {
  const fs::path dir =
      fs::path("test_output") / "phase_statistics" / ("np" + std::to_string(core::Comm().size()));
  const auto mesh = box();
  const auto metrics = mesh::compute_dual_metrics(mesh);
  auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  const analysis::PhaseStatisticsOptions options{period, bins, 0.2, rho, "plane"};
  // A plane subset: nodes near y = 0.5.
  const auto plane = analysis::nodes_near_plane(local, {0, 0.5, 0}, {0, 1, 0}, 1e-9);
  CHECK(local.comm.sum(std::int64_t(plane.size())) == 7 * 4);
  analysis::PhaseStatistics stats(local, options, plane);
  run_cycles(local, stats, 0, 5);
  const auto arrays = stats.checkpoint_arrays();
  flow::FlowState state;
  fill(local, 0, 0, state);
  io::CheckpointWriter writer(local, io::mesh_hash(mesh), dir);
  const auto path = writer.write(state, 1, 1e-3, arrays);

  for (MPI_Comm comm : {MPI_COMM_WORLD, MPI_COMM_SELF}) {
    auto other = mesh::distribute(mesh, metrics, comm, {2, mesh::PartitionMethod::metis});
    const auto other_plane = analysis::nodes_near_plane(other, {0, 0.5, 0}, {0, 1, 0}, 1e-9);
    analysis::PhaseStatistics back(other, options, other_plane);
    back.restore(io::CheckpointReader(other, io::mesh_hash(mesh), path));
    CHECK(back.cycles() == 5);
    int bad = 0;
    for (int b = 0; b < bins; ++b) {
      CHECK(back.count(b) == 5);
      for (std::size_t i = 0; i < other_plane.size(); ++i) {
        const auto& x = other.position[other_plane[i]];
        const double a = 0.1 * (1 + x.y());
        // Over 5 cycles e = (1,-1,1,-1,1) has mean 0.2; g = (1,1,1,1,-1) has RMS 0.8.
        bad += std::abs(back.mean(b, int(i), 0) - mean_u(x, b) - 0.2 * a) > 1e-14;
        bad += std::abs(back.rms(b, int(i), 2) - 1.6 * a) > 1e-14;
      }
    }
    CHECK(other.comm.sum(std::int64_t(bad)) == 0);
    analysis::PhaseStatistics other_bins(other, {period, 2, 0.2, rho, "plane"}, other_plane);
    CHECK_THROWS_WITH(other_bins.restore(io::CheckpointReader(other, io::mesh_hash(mesh), path)),
                      doctest::Contains("saved with period 0.8 s, 4 bins"));
  }

  // Output: one XDMF step per bin, NaN off the plane.
  const auto xmf = stats.write(mesh, metrics, dir / "out");
  CHECK(fs::exists(xmf));
  if (local.comm.root()) {
    const auto u = io::read_nodal_field(dir / "out" / "plane_000002.h5", "mean_velocity");
    const auto k = io::read_nodal_field(dir / "out" / "plane_000002.h5", "k");
    int on = 0, off = 0, wrong = 0;
    for (mesh::GlobalIndex m = 0; m < mesh.num_nodes(); ++m) {
      const auto& x = mesh.nodes[m];
      if (std::abs(x.y() - 0.5) < 1e-9) {
        ++on;
        wrong += std::abs(u[3 * m] - mean_u(x, 2) - 0.2 * 0.1 * (1 + x.y())) > 1e-14;
        wrong += !(k[m] > 0);
      } else {
        off += std::isnan(u[3 * m]) && std::isnan(k[m]);
      }
    }
    CHECK(on == 28);
    CHECK(off == mesh.num_nodes() - 28);
    CHECK(wrong == 0);
  }
}

TEST_CASE("section region: the nodes of every cell a plane cuts inside the window") {
  // Unit box of 4^3 hexahedra (cells 0.25 wide): a plane between node layers cuts one layer of
  // cells, a plane on a node layer the two layers it bounds; the window keeps the cells whose
  // bounding box overlaps it.
  mesh::BoxSpec spec;
  spec.cells = {4, 4, 4};
  const auto hexes = mesh::generate_box(spec);
  const auto hex_metrics = mesh::compute_dual_metrics(hexes);
  const auto hex_local =
      mesh::distribute(hexes, hex_metrics, MPI_COMM_WORLD, {2, mesh::PartitionMethod::metis});
  const Eigen::Vector3d x_axis{1, 0, 0}, lo{-1, -1, -1}, hi{2, 2, 2};
  const auto covered = [&](const Eigen::Vector3d& point, const Eigen::Vector3d& window_hi) {
    return hex_local.comm.sum(static_cast<std::int64_t>(
        analysis::nodes_of_cut_cells(hex_local, hexes, hex_metrics, point, x_axis, lo, window_hi)
            .size()));
  };
  CHECK(mesh::cells_cut_by_plane(hexes, {0.3, 0, 0}, x_axis, lo, hi).size() == 16);
  CHECK(covered({0.3, 0, 0}, hi) == 2 * 25);
  CHECK(mesh::cells_cut_by_plane(hexes, {0.5, 0, 0}, x_axis, lo, hi).size() == 32);
  CHECK(covered({0.5, 0, 0}, hi) == 3 * 25);
  CHECK(mesh::cells_cut_by_plane(hexes, {0.3, 0, 0}, x_axis, lo, {2, 0.2, 2}).size() == 4);
  CHECK(covered({0.3, 0, 0}, {2, 0.2, 2}) == 2 * 2 * 5);
  CHECK(mesh::cells_cut_by_plane(hexes, {1.5, 0, 0}, x_axis, lo, hi).empty());

  // A tilted plane through tetrahedra: every point of the plane inside the window lies in a
  // cell whose nodes are all covered (what interpolation on the plane needs), which a slab of
  // nodes within half a cell of the plane does not give.
  const auto tets = box();  // 6 x 4 x 3 cells of the unit box, split into tetrahedra
  const auto metrics = mesh::compute_dual_metrics(tets);
  const Eigen::Vector3d point{0.5, 0.5, 0.5}, normal = Eigen::Vector3d(1, 0.3, 0.2).normalized();
  const Eigen::Vector3d window_lo{0, 0.1, 0.1}, window_hi{1, 0.9, 0.9};
  std::vector<char> marked(tets.nodes.size(), 0);
  for (auto c : mesh::cells_cut_by_plane(tets, point, normal, window_lo, window_hi))
    for (auto n : tets.cell(c)) marked[static_cast<std::size_t>(n)] = 1;
  std::vector<char> slab(tets.nodes.size(), 0);
  for (std::size_t n = 0; n < tets.nodes.size(); ++n)
    slab[n] = std::abs((tets.nodes[n] - point).dot(normal)) <= 0.5 / 6;
  const mesh::PointLocator locator(tets);
  const Eigen::Vector3d e1 = normal.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d e2 = normal.cross(e1);
  int inside = 0, complete = 0, slab_complete = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const Eigen::Vector3d x = point + (i / 40.0 - 0.5) * 0.8 * e1 + (j / 40.0 - 0.5) * 0.8 * e2;
      if (!((x.array() >= window_lo.array()).all() && (x.array() <= window_hi.array()).all()))
        continue;
      const auto at = locator.locate(x);
      REQUIRE(at);
      ++inside;
      bool all = true, all_slab = true;
      for (int k = 0; k < at->count; ++k)
        all = all && marked[static_cast<std::size_t>(at->nodes[k])],
        all_slab = all_slab && slab[static_cast<std::size_t>(at->nodes[k])];
      complete += all, slab_complete += all_slab;
    }
  CHECK(inside > 500);
  CHECK(complete == inside);
  CHECK(slab_complete < inside);
}
