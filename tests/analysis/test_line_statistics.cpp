// Line statistics (analysis/line_statistics.hpp) of a synthetic field that is linear in space at
// every instant, so that the cell interpolation at the line's points is exact: a phase-locked
// sine plus cycle-to-cycle fluctuations from exactly zero-mean, orthogonal +-1 sequences over 4
// cycles give known phase means, RMS values and Reynolds stresses. The accumulators agree bit
// for bit with the same line on one rank, a checkpoint mid-run restored at the world size and
// at one rank continues to the same bits, points outside the mesh are left out and counted,
// and the scene refuses a degenerate line, too few points and a zero section normal by key.
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/line_statistics.hpp"
#include "analysis/run_analysis.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "scene/scene_keys_analysis.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

constexpr double period = 0.4, rho = 1060;
constexpr int bins = 4, cycles = 4;

mesh::Mesh box() {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::BoxCellType::tetra;
  spec.cells = {5, 4, 3};
  return mesh::generate_box(spec);
}

// Over cycles 0..3: mean 0, mean square 1, mean product 0.
double e(std::int64_t c) {
  return c % 2 ? -1.0 : 1.0;
}
double f(std::int64_t c) {
  return (c / 2) % 2 ? -1.0 : 1.0;
}

// Amplitudes, linear in x (so the interpolation reproduces them at any point).
double amp_c(const Eigen::Vector3d& x) {
  return 0.1 + 0.2 * x.x() - 0.05 * x.z();
}
double amp_d(const Eigen::Vector3d& x) {
  return 0.3 - 0.1 * x.y();
}
double amp_e(const Eigen::Vector3d& x) {
  return 0.05 + 0.1 * x.z();
}
double phase(int b) {
  return 2 * M_PI * (b + 0.5) / bins;
}
double mean_u(const Eigen::Vector3d& x, int b) {
  return 1 + x.x() - 2 * x.y() + 0.5 * x.z() * std::sin(phase(b));
}

// The state at the centre of bin b of cycle c: u = mean + C e, v = 0.5 + D e, w = -1 + E f,
// p = 10 x + 3 C f.
flow::FlowState state_at(const mesh::LocalMesh& local, std::int64_t c, int b) {
  flow::FlowState s;
  s.time = 0.1 + period * (double(c) + (b + 0.5) / bins);  // start_time 0.1
  for (int i = 0; i < local.num_local(); ++i) {
    const auto& x = local.position[i];
    s.velocity.emplace_back(mean_u(x, b) + amp_c(x) * e(c), 0.5 + amp_d(x) * e(c),
                            -1 + amp_e(x) * f(c));
    s.pressure.push_back(10 * x.x() + 3 * amp_c(x) * f(c));
  }
  return s;
}

void run_cycles(const mesh::LocalMesh& local, analysis::LineStatistics& line, int first, int last) {
  for (int c = first; c < last; ++c)
    for (int b = 0; b < bins; ++b) line.add(state_at(local, c, b));
}

const analysis::PhaseStatisticsOptions options{period, bins, 0.1, rho, "diag"};
const analysis::LineSpec diagonal{{0.05, 0.9, 0.1}, {0.95, 0.1, 0.85}, 7};

// Every accumulated number of two lines over the same points, compared bit for bit.
bool same_bits(const analysis::LineStatistics& a, const analysis::LineStatistics& b) {
  if (a.points().size() != b.points().size()) return false;
  for (int bin = 0; bin < bins; ++bin) {
    if (a.count(bin) != b.count(bin)) return false;
    for (int i = 0; i < int(a.points().size()); ++i)
      if (a.moments(bin, i).mean != b.moments(bin, i).mean ||
          a.moments(bin, i).m2 != b.moments(bin, i).m2)
        return false;
  }
  return a.cycles() == b.cycles();
}

}  // namespace

TEST_CASE("line statistics: exact phase means, RMS and stresses; same bits on one rank") {
  const auto mesh = box();
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  analysis::LineStatistics line(mesh, metrics, local, options, diagonal, "statistics.diag");
  REQUIRE(line.points().size() == 7);
  CHECK(line.outside() == 0);
  run_cycles(local, line, 0, cycles);
  // Not sampled: before start_time.
  auto early = state_at(local, 0, 0);
  early.time = 0.05;
  line.add(early);

  // Round-off only: the interpolation weights sum to 1 within a few ulps and 16 Welford
  // updates of O(1) values lose a few more; 1e-13 is far below any modelling error.
  const double tol = 1e-13;
  CHECK(line.cycles() == cycles);
  int bad = 0;
  for (int b = 0; b < bins; ++b) {
    CHECK(line.count(b) == cycles);
    for (int i = 0; i < 7; ++i) {
      const auto& x = line.points()[i].position;
      const double c = amp_c(x), d = amp_d(x), w = amp_e(x);
      bad += std::abs(line.mean(b, i, 0) - mean_u(x, b)) > tol;
      bad += std::abs(line.mean(b, i, 1) - 0.5) > tol;
      bad += std::abs(line.mean(b, i, 2) + 1) > tol;
      bad += std::abs(line.mean(b, i, 3) - 10 * x.x()) > 10 * tol;
      bad += std::abs(line.rms(b, i, 0) - std::abs(c)) > tol;
      bad += std::abs(line.rms(b, i, 1) - std::abs(d)) > tol;
      bad += std::abs(line.rms(b, i, 2) - std::abs(w)) > tol;
      bad += std::abs(line.rms(b, i, 3) - 3 * std::abs(c)) > tol;
      bad += std::abs(line.reynolds_stress(b, i, 0, 1) - c * d) > tol;  // e e
      bad += std::abs(line.reynolds_stress(b, i, 0, 2)) > tol;          // e f
      bad += std::abs(line.reynolds_stress(b, i, 1, 2)) > tol;
      bad += std::abs(line.kinetic_energy(b, i) - 0.5 * rho * (c * c + d * d + w * w)) > rho * tol;
    }
  }
  CHECK(bad == 0);

  // The same line on one rank: Probes gives the same bits at any rank count.
  const auto serial = mesh::distribute(mesh, metrics, MPI_COMM_SELF);
  analysis::LineStatistics alone(mesh, metrics, serial, options, diagonal, "statistics.diag");
  run_cycles(serial, alone, 0, cycles);
  CHECK(same_bits(line, alone));

  // The CSV: header, one row per bin and point, arc length, samples and k.
  const fs::path dir =
      fs::path("test_output") / "line_statistics" / ("np" + std::to_string(local.comm.size()));
  const auto csv = line.write(dir);
  local.comm.barrier();
  if (local.comm.root()) {
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    CHECK(header ==
          "bin,phase_time,s,x,y,z,samples,mean_u,mean_v,mean_w,mean_p,rms_u,rms_v,rms_w,rms_p,"
          "uu,vv,ww,uv,vw,uw,k");
    int rows = 0;
    const double length = (diagonal.end - diagonal.origin).norm();
    for (std::string row; std::getline(in, row); ++rows) {
      std::vector<double> v;
      std::stringstream ss(row);
      for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
      REQUIRE(v.size() == 22);
      const int b = rows / 7, i = rows % 7;
      CHECK(v[0] == b);
      CHECK(v[1] == doctest::Approx(period * (b + 0.5) / bins).epsilon(1e-15));
      CHECK(v[2] == doctest::Approx(length * i / 6).epsilon(1e-15));
      CHECK(v[6] == cycles);
      CHECK(v[11] == line.rms(b, i, 0));  // 17 digits: the double itself
      CHECK(v[21] == line.kinetic_energy(b, i));
    }
    CHECK(rows == bins * 7);
  }
}

TEST_CASE("line statistics: a checkpoint mid-run continues to the same bits") {
  const auto mesh = box();
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  analysis::LineStatistics straight(mesh, metrics, local, options, diagonal, "statistics.diag");
  run_cycles(local, straight, 0, cycles);

  analysis::LineStatistics first_half(mesh, metrics, local, options, diagonal, "statistics.diag");
  run_cycles(local, first_half, 0, 2);
  const fs::path dir = fs::path("test_output") / "line_statistics_restart" /
                       ("np" + std::to_string(local.comm.size()));
  io::CheckpointWriter writer(local, io::mesh_hash(mesh), dir);
  const auto path =
      writer.write(state_at(local, 1, bins - 1), 8, 1e-3, first_half.checkpoint_arrays());

  for (MPI_Comm comm : {MPI_COMM_WORLD, MPI_COMM_SELF}) {
    const auto other = mesh::distribute(mesh, metrics, comm);
    analysis::LineStatistics back(mesh, metrics, other, options, diagonal, "statistics.diag");
    back.restore(io::CheckpointReader(other, io::mesh_hash(mesh), path));
    CHECK(back.count(0) == 2);
    run_cycles(other, back, 2, cycles);
    CHECK(same_bits(back, straight));

    analysis::LineStatistics shifted(
        mesh, metrics, other, options,
        {diagonal.origin, diagonal.end + Eigen::Vector3d(0, 0, 0.01), 7}, "statistics.diag");
    CHECK_THROWS_WITH(shifted.restore(io::CheckpointReader(other, io::mesh_hash(mesh), path)),
                      doctest::Contains("saved point 1 is at"));
    analysis::LineStatistics other_bins(mesh, metrics, other, {period, 2, 0.1, rho, "diag"},
                                        diagonal, "statistics.diag");
    CHECK_THROWS_WITH(other_bins.restore(io::CheckpointReader(other, io::mesh_hash(mesh), path)),
                      doctest::Contains("saved with period 0.4 s, 4 bins"));
  }
}

TEST_CASE("line statistics: points outside the mesh are left out; bad lines are refused") {
  const auto mesh = box();
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
  // x = -1.05, -0.55, -0.05 are outside the unit box, 0.45 and 0.95 inside.
  analysis::LineStatistics half(mesh, metrics, local, options,
                                {{-1.05, 0.5, 0.5}, {0.95, 0.5, 0.5}, 5}, "statistics.half");
  CHECK(half.outside() == 3);
  REQUIRE(half.arc_length().size() == 2);
  CHECK(half.arc_length()[0] == doctest::Approx(1.5).epsilon(1e-15));
  CHECK_THROWS_WITH(analysis::LineStatistics(mesh, metrics, local, options,
                                             {{2, 2, 2}, {3, 3, 3}, 4}, "statistics.away"),
                    doctest::Contains("statistics.away: none of the 4 points"));
  CHECK_THROWS_WITH(
      analysis::LineStatistics(mesh, metrics, local, options, {{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 4},
                               "statistics.dot"),
      doctest::Contains("statistics.dot.end: the line has zero length"));

  // The scene: the key at fault is named, with its file and line.
  auto error_of = [&](const std::string& tables) {
    const std::string text =
        "[mesh]\nsource = \"box\"\n[mesh.box]\ncells = [4, 4, 4]\n[time]\nend = 1.0\n" + tables;
    try {
      const auto scene = scene::parse_scene(text, "line.toml");
      scene::read_analysis_options(scene, mesh);
    } catch (const scene::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto degenerate = error_of(
      "[statistics.l]\nregion = \"line\"\norigin = [0.5, 0.5, 0.5]\nend = [0.5, 0.5, 0.5]\n");
  CHECK(degenerate.find("line.toml:10:") != std::string::npos);
  CHECK(degenerate.find("key 'statistics.l.end': the line has zero length") != std::string::npos);
  const auto one_point = error_of(
      "[statistics.l]\nregion = \"line\"\norigin = [0, 0, 0]\nend = [1, 1, 1]\npoints = 1\n");
  CHECK(one_point.find("key 'statistics.l.points'") != std::string::npos);
  const auto zero_normal =
      error_of("[section.s]\npoint = [0.5, 0.5, 0.5]\nnormal = [0.0, 0.0, 0.0]\n");
  CHECK(zero_normal.find("key 'section.s.normal': the normal is zero") != std::string::npos);
  const auto no_radius = error_of(
      "[section.s]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\nbound = "
      "\"disc\"\n");
  CHECK(no_radius.find("key 'section.s.radius': required key is missing") != std::string::npos);
  CHECK(error_of("[statistics.l]\nregion = \"line\"\norigin = [0, 0, 0]\nend = [1, 1, 1]\n"
                 "[section.s]\npoint = [0, 0, 0]\nnormal = [0, 0, 1]\n") == "no error");
}
