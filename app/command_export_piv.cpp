// `valsalva export-piv STATS.xmf --origin x,y,z --ex x,y,z --ey x,y,z --out FILE.csv [--grid
// NX,NY] [--spacing m] [--first x,y] [--bin b ...] [--overwrite]`: samples the phase statistics
// a run wrote (analysis::PhaseStatistics) on a regular PIV grid of the plane, exactly as
// `valsalva compare-piv` samples them, and writes one PIV frame per phase bin that holds samples
// (column `phase` = the bin's phase time) in the CSV compare-piv reads (analysis/piv_export.hpp).
// An existing FILE is kept unless --overwrite. Runs on rank 0.
#include "app/command_export_piv.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "analysis/piv_export.hpp"
#include "analysis/statistics_files.hpp"
#include "app/piv_plane_options.hpp"
#include "core/numeric_table.hpp"

namespace valsalva::app {

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string stats, out;
  PivPlaneOptions plane;
  std::vector<double> first{0.0, 0.0};
  std::vector<int> grid{63, 79};
  double spacing = 0.68e-3;
  std::vector<int> bins;  // empty: every bin with samples
  bool overwrite = false;
};

int run(const Options& o) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return 0;
  const fs::path out(o.out);
  if (!o.overwrite && fs::exists(out))
    throw std::invalid_argument(
        fmt::format("export-piv: '{}' exists; --overwrite replaces it", out.string()));
  const fs::path stats(o.stats);
  const fs::path dir = stats.parent_path();
  const std::string name = stats.stem().string();
  const fs::path mesh_file = dir / (name + "_mesh.h5");
  const fs::path phases_file = dir / (name + "_phases.csv");
  const auto mesh = analysis::read_statistics_mesh(mesh_file);
  const auto phases = core::read_numeric_table(phases_file, core::TableHeader::required);
  const auto phase_times = phases.column("phase_time");
  const auto samples = phases.column("samples");
  std::vector<int> bins = o.bins;
  if (bins.empty()) {
    for (std::size_t b = 0; b < samples.size(); ++b)
      if (samples[b] > 0) bins.push_back(static_cast<int>(b));
    if (bins.empty())
      throw std::runtime_error(
          fmt::format("export-piv: no phase bin of '{}' holds samples (column 'samples' all 0)",
                      phases_file.string()));
  }
  for (int b : bins)
    if (b < 0 || b >= static_cast<int>(phase_times.size()))
      throw std::invalid_argument(fmt::format("export-piv: --bin {} but '{}' lists bins 0 to {}", b,
                                              phases_file.string(), phase_times.size() - 1));

  const analysis::PivPlane plane(Eigen::Vector3d(o.plane.origin.data()),
                                 Eigen::Vector3d(o.plane.ex.data()),
                                 Eigen::Vector3d(o.plane.ey.data()));
  analysis::PivGrid grid;
  grid.nx = o.grid[0], grid.ny = o.grid[1], grid.spacing = o.spacing;
  grid.x0 = o.first[0], grid.y0 = o.first[1];
  const analysis::PivFrame layout = analysis::piv_grid_frame(grid);
  const mesh::PointLocator locator(mesh);
  const analysis::PivSampler sampler(locator, plane, layout);

  analysis::PivData data;
  data.frame_key = "phase";
  std::size_t masked = 0;
  for (int b : bins) {
    const auto sim =
        analysis::read_statistics_bin(dir / fmt::format("{}_{:06d}.h5", name, b), mesh, mesh_file);
    analysis::PivFrame frame = layout;
    analysis::sample_statistics(sampler, sim, frame);
    frame.phase = phase_times[b];
    data.has_rms = sim.has_rms();
    masked += frame.size() - frame.valid_count();
    data.frames.push_back(std::move(frame));
  }
  const std::string comment = fmt::format(
      "PIV grid of '{}' (valsalva export-piv): {} x {} vectors {} m apart from ({}, {}) m in the\n"
      "plane origin ({}, {}, {}) m, x axis ({}, {}, {}), y axis ({}, {}, {}); one frame per phase\n"
      "bin (phase = its phase time, s); masked: outside the mesh or the statistics' nodes",
      o.stats, grid.nx, grid.ny, grid.spacing, grid.x0, grid.y0, o.plane.origin[0],
      o.plane.origin[1], o.plane.origin[2], o.plane.ex[0], o.plane.ex[1], o.plane.ex[2],
      o.plane.ey[0], o.plane.ey[1], o.plane.ey[2]);
  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  analysis::write_piv_csv(out, data, comment);
  fmt::print(
      "export-piv: {} frames of {} vectors ({} of {} masked: outside the statistics) -> '{}'\n",
      data.frames.size(), layout.size(), masked, data.frames.size() * layout.size(), out.string());
  return 0;
}

}  // namespace

CLI::App* add_export_piv(CLI::App& cli, std::function<int()>& action) {
  auto o = std::make_shared<Options>();
  auto* c = cli.add_subcommand(
      "export-piv", "Write saved phase statistics as a PIV file (a grid of the PIV plane)");
  c->add_option("stats", o->stats, "Statistics .xmf written by a run (PhaseStatistics)")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("--out", o->out, "PIV CSV file to write (read by compare-piv)")->required();
  add_piv_plane_options(c, o->plane);
  c->add_option("--grid", o->grid,
                "Vectors along the PIV x and y axes (NX,NY; default 63,79: the valve case's PIV)")
      ->expected(2)
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  c->add_option("--spacing", o->spacing,
                "Distance between neighbouring vectors, m (default 0.00068)")
      ->check(CLI::PositiveNumber);
  c->add_option("--first", o->first,
                "PIV-plane coordinates of the first vector, m (x,y; default 0,0)")
      ->expected(2)
      ->delimiter(',');
  c->add_option("--bin", o->bins, "Phase bins to write (default: every bin with samples)");
  c->add_flag("--overwrite", o->overwrite, "Replace an existing --out file");
  action = [o] { return run(*o); };
  return c;
}

}  // namespace valsalva::app
