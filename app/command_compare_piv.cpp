// `valsalva compare-piv STATS.xmf PIV_FILE --origin x,y,z --ex x,y,z --ey x,y,z [--line ...]`:
// reads the statistics written by analysis::PhaseStatistics::write (mesh, one HDF5 file per phase
// bin, <name>_phases.csv), reads the PIV file, matches every PIV frame to the bin whose phase time
// is nearest to the frame's phase/time value (or to --bin), and writes metrics.csv, frame_<i>.csv,
// profile_<line>_<i>.csv and frame_<i>.png (analysis/plot_piv.py) into --out (an --out holding
// an earlier comparison's metrics.csv is kept unless --overwrite). PIV files in other
// units than m and m/s take --length-scale / --velocity-scale (analysis::PivUnits). Runs on rank 0.
#include "app/command_compare_piv.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "analysis/piv_compare.hpp"
#include "analysis/probes.hpp"
#include "analysis/statistics_files.hpp"
#include "app/piv_plane_options.hpp"
#include "run/data_dir.hpp"

namespace valsalva::app {

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string stats, piv, out = "piv-compare";
  PivPlaneOptions plane;
  std::vector<std::string> lines;
  int bin = -1;
  int line_points = 60;
  analysis::PivUnits units;  // file units -> m, m/s
  bool plot = true;
  bool overwrite = false;
};

analysis::ProfileLine parse_line(const std::string& text) {
  // name:x0,y0,x1,y1
  const auto colon = text.find(':');
  analysis::ProfileLine l;
  std::vector<double> v;
  if (colon != std::string::npos) {
    l.name = text.substr(0, colon);
    std::stringstream ss(text.substr(colon + 1));
    std::string item;
    while (std::getline(ss, item, ',')) {
      try {
        v.push_back(std::stod(item));
      } catch (const std::exception&) {
        v.clear();
        break;
      }
    }
  }
  if (v.size() != 4 || l.name.empty())
    throw std::invalid_argument(
        fmt::format("compare-piv: --line '{}' is not NAME:x0,y0,x1,y1 (PIV-plane metres)", text));
  l.a = {v[0], v[1]}, l.b = {v[2], v[3]};
  return l;
}

int run(const Options& o) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return 0;
  if (!o.overwrite && fs::exists(fs::path(o.out) / "metrics.csv"))
    throw std::invalid_argument(
        fmt::format("compare-piv: '{}' holds an earlier comparison (metrics.csv); --overwrite "
                    "replaces it",
                    o.out));
  const fs::path stats(o.stats);
  const fs::path dir = stats.parent_path();
  const std::string name = stats.stem().string();
  const fs::path mesh_file = dir / (name + "_mesh.h5");
  const auto mesh = analysis::read_statistics_mesh(mesh_file);
  const auto phase_times = analysis::read_phase_times(dir / (name + "_phases.csv"));
  const auto piv = analysis::read_piv(o.piv, o.units);
  const analysis::PivPlane plane(Eigen::Vector3d(o.plane.origin.data()),
                                 Eigen::Vector3d(o.plane.ex.data()),
                                 Eigen::Vector3d(o.plane.ey.data()));
  std::vector<analysis::ProfileLine> lines;
  for (const auto& l : o.lines) lines.push_back(parse_line(l)), lines.back().points = o.line_points;
  const mesh::PointLocator locator(mesh);
  fs::create_directories(o.out);

  std::vector<analysis::FrameComparison> all;
  for (std::size_t f = 0; f < piv.frames.size(); ++f) {
    const auto& frame = piv.frames[f];
    int bin = o.bin;
    if (bin < 0) {
      if (phase_times.size() == 1) {
        bin = 0;
      } else if (std::isnan(frame.phase)) {
        throw std::runtime_error(fmt::format(
            "compare-piv: PIV frame '{}' of '{}' has no phase/time and the statistics have {} "
            "bins: give --bin",
            frame.label, piv.source, phase_times.size()));
      } else {
        double best = INFINITY;
        for (std::size_t b = 0; b < phase_times.size(); ++b)
          if (std::abs(phase_times[b] - frame.phase) < best)
            best = std::abs(phase_times[b] - frame.phase), bin = int(b);
      }
    }
    if (bin >= int(phase_times.size()))
      throw std::invalid_argument(fmt::format(
          "compare-piv: --bin {} but the statistics have {} bins", bin, phase_times.size()));
    const auto sim = analysis::read_statistics_bin(dir / fmt::format("{}_{:06d}.h5", name, bin),
                                                   mesh, mesh_file);
    const analysis::PivSampler sampler(locator, plane, frame);
    auto c = analysis::compare_frame(frame, sampler, sim);
    const auto csv = fs::path(o.out) / fmt::format("frame_{:03d}.csv", f);
    analysis::write_comparison_csv(csv, frame, c);
    std::string profiles;
    // Nearest PIV point within 0.75 of the typical spacing (grid area / points).
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (std::size_t i = 0; i < frame.size(); ++i)
      xmin = std::min(xmin, frame.x[i]), xmax = std::max(xmax, frame.x[i]),
      ymin = std::min(ymin, frame.y[i]), ymax = std::max(ymax, frame.y[i]);
    const double spacing = std::sqrt((xmax - xmin) * (ymax - ymin) / double(frame.size()));
    for (const auto& l : lines) {
      const auto p = analysis::sample_profile(l, sampler, frame, sim, 0.75 * spacing);
      const auto path = fs::path(o.out) / fmt::format("profile_{}_{:03d}.csv", l.name, f);
      analysis::write_profile_csv(path, p);
      profiles += fmt::format(" --profile '{}'", path.string());
    }
    fmt::print(
        "frame {} '{}' -> bin {} (phase time {:.4g} s): u RMSE {:.4g} m/s, normalised {:.3g}, "
        "correlation {:.4f}; v RMSE {:.4g} m/s; {} points, {} masked, {} outside\n",
        f, frame.label, bin, phase_times[bin], c.u.rmse, c.u.normalised_error, c.u.correlation,
        c.v.rmse, c.u.points, c.masked, c.outside);
    if (o.plot) {
      const auto png = fs::path(o.out) / fmt::format("frame_{:03d}.png", f);
      const std::string cmd = fmt::format(
          "/usr/bin/python3 '{}/analysis/plot_piv.py' '{}' '{}'{} --title '{}: PIV vs simulation "
          "bin {}'",
          run::data_dir().string(), csv.string(), png.string(), profiles, frame.label, bin);
      if (std::system(cmd.c_str()) != 0)
        fmt::print(stderr, "compare-piv: warning: plot failed ({})\n", cmd);
    }
    all.push_back(std::move(c));
  }
  analysis::write_metrics_csv(fs::path(o.out) / "metrics.csv", all);
  fmt::print("compare-piv: {} frames, results in '{}'\n", all.size(), o.out);
  return 0;
}

}  // namespace

CLI::App* add_compare_piv(CLI::App& cli, std::function<int()>& action) {
  auto o = std::make_shared<Options>();
  auto* c = cli.add_subcommand("compare-piv", "Compare PIV data with saved phase statistics");
  c->add_option("stats", o->stats, "Statistics .xmf written by a run (PhaseStatistics)")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("piv", o->piv, "PIV file: CSV or Tecplot ASCII (m, m/s unless scaled)")
      ->required()
      ->check(CLI::ExistingFile);
  add_piv_plane_options(c, o->plane);
  c->add_option("--line", o->lines, "Profile line NAME:x0,y0,x1,y1 in PIV-plane metres");
  c->add_option("--line-points", o->line_points, "Points per profile line");
  c->add_option("--bin", o->bin, "Statistics bin for every frame (default: nearest phase)");
  c->add_option("--out", o->out, "Output folder");
  c->add_option("--length-scale", o->units.length,
                "Metres per PIV length unit, applied on reading (0.001 for mm)")
      ->check(CLI::PositiveNumber);
  c->add_option("--velocity-scale", o->units.velocity,
                "m/s per PIV velocity unit, applied on reading (0.001 for mm/s)")
      ->check(CLI::PositiveNumber);
  c->add_flag("!--no-plot", o->plot, "Do not make PNG plots");
  c->add_flag("--overwrite", o->overwrite, "Replace the results of an earlier comparison in --out");
  action = [o] { return run(*o); };
  return c;
}

}  // namespace valsalva::app
