// `valsalva plot-valve RUN_DIR [--out DIR] [--period s] [--cycle-offset s] [--diastole f]
// [--overwrite]`: TPG, flow rate, orifice area and opening ratio, leaflet tips against time with
// the reference instants of the design note (analysis/plot_valve.py), per-cycle TPG extremes from
// valve_cycles.csv, and for a valve in a lumped circulation the ventricle and aorta pressures with
// per-cycle volumes (circulation_cycles.csv); PNGs and plotted.json in DIR (default
// RUN_DIR/plots). Existing PNGs are kept unless --overwrite. Runs on rank 0.
#include "app/command_plot_valve.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "run/data_dir.hpp"

namespace valsalva::app {

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string run_dir, out;
  double period = 1.0, cycle_offset = 0.0, diastole = 0.6;
  bool overwrite = false;
};

int run(const Options& o) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return 0;
  if (!fs::is_directory(o.run_dir))
    throw std::runtime_error(fmt::format("plot-valve: run folder '{}' does not exist", o.run_dir));
  const auto csv = fs::path(o.run_dir) / "valve.csv";
  if (!fs::is_regular_file(csv))
    throw std::runtime_error(fmt::format(
        "plot-valve: '{}' does not exist (a run writes it with a [valve] section)", csv.string()));
  const fs::path out = o.out.empty() ? fs::path(o.run_dir) / "plots" : fs::path(o.out);
  for (const char* file :
       {"tpg.png", "flow_rate.png", "opening_area.png", "tips.png", "tpg_cycles.png",
        "profiles.png", "profiles.csv", "circulation.png", "circulation_cycles.csv"})
    if (!o.overwrite && fs::exists(out / file))
      throw std::runtime_error(
          fmt::format("plot-valve: '{}' exists; --overwrite replaces it", (out / file).string()));
  fs::create_directories(out);
  const std::string cmd = fmt::format(
      "/usr/bin/python3 '{}/analysis/plot_valve.py' '{}' '{}' --period {:.17g} --cycle-offset "
      "{:.17g} --diastole {:.17g}",
      run::data_dir().string(), o.run_dir, out.string(), o.period, o.cycle_offset, o.diastole);
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error(fmt::format("plot-valve: plotting '{}' failed", csv.string()));
  fmt::print("plot-valve: plots of '{}' in '{}'\n", csv.string(), out.string());
  return 0;
}

}  // namespace

CLI::App* add_plot_valve(CLI::App& cli, std::function<int()>& action) {
  auto o = std::make_shared<Options>();
  auto* c = cli.add_subcommand(
      "plot-valve",
      "PNG plots of a run's valve.csv: TPG, flow rate, orifice area, leaflet tips vs time with "
      "the reference instants t1-t6; with a lumped circulation, the ventricle and aorta "
      "pressures and per-cycle volumes (circulation_cycles.csv)");
  c->add_option("run_dir", o->run_dir, "Run folder holding valve.csv")->required();
  c->add_option("--out", o->out, "Output folder (default RUN_DIR/plots)");
  c->add_option("--period", o->period, "Cardiac period (s)")->check(CLI::PositiveNumber);
  c->add_option("--cycle-offset", o->cycle_offset, "Time at which a cycle starts (s)");
  c->add_option("--diastole", o->diastole,
                "Fraction of the period from which circulation_cycles.csv's diastolic mean flow "
                "is taken (0.6)")
      ->check(CLI::Range(0.0, 0.99));
  c->add_flag("--overwrite", o->overwrite, "Replace existing plots and tables");
  action = [o] { return run(*o); };
  return c;
}

}  // namespace valsalva::app
