// `valsalva psd PROBES.csv --column NAME [--column NAME2 ...] [--segments N | --segment-length N]
// [--overlap 0.5] [--out DIR] [--no-plot]`: Welch power spectral density (analysis/welch_psd.hpp)
// of columns of a probe CSV (analysis::ProbeCsv: "time,<probe>_u,..."). Writes DIR/psd_<column>.csv
// (frequency [Hz], psd [units^2/Hz]) and DIR/psd.png (analysis/plot_psd.py). Sample times that are
// not uniform to round-off (a run whose dt changed) are resampled linearly onto a uniform grid
// with the mean spacing and the same number of samples, and the command says so; times that do
// not increase are refused. Runs on rank 0.
#include "app/command_psd.hpp"

#include <fmt/format.h>
#include <fmt/os.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "analysis/probes.hpp"
#include "analysis/uniform_sampling.hpp"
#include "analysis/welch_psd.hpp"
#include "run/data_dir.hpp"

namespace valsalva::app {

namespace {

namespace fs = std::filesystem;

// Fewer samples per segment than this leave too few frequency bins to read a spectrum.
constexpr std::size_t min_segment_length = 8;

struct Options {
  std::string file, out = "psd";
  std::vector<std::string> columns;
  int segments = 0;
  int segment_length = 0;
  double overlap = 0.5;
  bool plot = true;
};

// Characters outside [A-Za-z0-9_.-] become '_' in file names.
std::string file_stem(const std::string& column) {
  std::string s = column;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  return "psd_" + s;
}

// K segments overlapping by a fraction o span L (1 + (K - 1)(1 - o)) samples.
std::size_t length_for_segments(std::size_t n, int segments, double overlap) {
  return std::size_t(std::floor(double(n) / (1 + (segments - 1) * (1 - overlap))));
}

int run(const Options& o) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return 0;
  if (o.columns.empty()) throw std::invalid_argument("psd: give at least one --column");
  if (!(o.overlap >= 0 && o.overlap < 1))
    throw std::invalid_argument(fmt::format("psd: --overlap {} must be in [0, 1)", o.overlap));
  const analysis::ProbeSeries series = analysis::read_probe_csv(o.file);
  if (series.columns.empty() || series.columns.front() != "time")
    throw std::runtime_error(
        fmt::format("psd: probe file '{}' does not start with a 'time' column", o.file));
  for (const auto& c : o.columns)
    if (std::find(series.columns.begin() + 1, series.columns.end(), c) == series.columns.end()) {
      std::string known;
      for (std::size_t i = 1; i < series.columns.size(); ++i)
        known += (i > 1 ? ", " : "") + series.columns[i];
      throw std::invalid_argument(
          fmt::format("psd: probe file '{}' has no column '{}' (columns: {})", o.file, c, known));
    }
  const std::vector<double> time = series.column("time");
  const analysis::Sampling sampling =
      analysis::check_sampling(time, fmt::format("psd: '{}'", o.file));
  const std::size_t n = time.size();
  if (!sampling.uniform)
    fmt::print(
        "psd: '{}': sample spacing is not uniform (dt from {:.6g} to {:.6g} s): resampled "
        "linearly onto {} uniform samples, dt = {:.6g} s\n",
        o.file, sampling.dt_min, sampling.dt_max, n, sampling.dt_mean);

  analysis::WelchOptions w;
  w.overlap = o.overlap;
  if (o.segment_length > 0)
    w.segment_length = std::size_t(o.segment_length);
  else
    w.segment_length = length_for_segments(n, o.segments > 0 ? o.segments : 8, o.overlap);
  if (w.segment_length < min_segment_length || w.segment_length > n)
    throw std::invalid_argument(fmt::format(
        "psd: '{}' has {} samples, too short for segments of {} samples (need {} <= segment "
        "length <= samples; {})",
        o.file, n, w.segment_length, min_segment_length,
        o.segment_length > 0 ? "lower --segment-length" : "use fewer --segments or more samples"));

  fs::create_directories(o.out);
  const double fs_hz = 1.0 / sampling.dt_mean;
  std::string plot_args;
  for (const auto& c : o.columns) {
    std::vector<double> v = series.column(c);
    if (!sampling.uniform) v = analysis::resample_uniform(time, v, n);
    const analysis::PowerSpectrum s = analysis::welch_psd(v, fs_hz, w);
    // Finite samples can still overflow in the squares (|x| ~ 1e155 and beyond).
    if (!std::all_of(s.psd.begin(), s.psd.end(), [](double p) { return std::isfinite(p); }))
      throw std::runtime_error(fmt::format(
          "psd: column '{}' of '{}': the spectrum overflows (values up to {:.3g}); rescale the "
          "series",
          c, o.file, *std::max_element(v.begin(), v.end(), [](double a, double b) {
            return std::abs(a) < std::abs(b);
          })));
    const fs::path csv = fs::path(o.out) / (file_stem(c) + ".csv");
    {
      auto f = fmt::output_file(csv.string());
      f.print("frequency,psd\n");
      for (std::size_t k = 0; k < s.psd.size(); ++k)
        f.print("{:.10e},{:.10e}\n", s.frequency[k], s.psd[k]);
    }
    const auto peak = std::max_element(s.psd.begin() + 1, s.psd.end()) - s.psd.begin();
    double mean = 0, var = 0;
    for (double x : v) mean += x / double(n);
    for (double x : v) var += (x - mean) * (x - mean) / double(n);
    fmt::print(
        "psd: {}: {} samples at {:.6g} Hz, {} segments of {} (overlap {}), df = {:.6g} Hz; peak "
        "{:.6g} Hz; variance {:.6g} (signal {:.6g}) -> '{}'\n",
        c, n, fs_hz, s.segments, w.segment_length, o.overlap, s.df, s.frequency[peak],
        analysis::spectrum_variance(s), var, csv.string());
    plot_args += fmt::format(" '{}'", csv.string());
  }
  if (o.plot) {
    const auto png = fs::path(o.out) / "psd.png";
    const std::string cmd = fmt::format(
        "/usr/bin/python3 '{}/analysis/plot_psd.py' '{}'{} --title 'Welch PSD of {}'",
        run::data_dir().string(), png.string(), plot_args, fs::path(o.file).filename().string());
    if (std::system(cmd.c_str()) != 0) fmt::print(stderr, "psd: warning: plot failed ({})\n", cmd);
  }
  return 0;
}

}  // namespace

CLI::App* add_psd(CLI::App& cli, std::function<int()>& action) {
  auto o = std::make_shared<Options>();
  auto* c = cli.add_subcommand("psd", "Power spectral density of probe time series (Welch)");
  c->add_option("probes", o->file, "Probe CSV written by a run (time,<probe>_u,...)")->required();
  c->add_option("--column", o->columns, "Column to analyse (repeat for several)")
      ->required()
      ->allow_extra_args(false);  // one name per --column, so a trailing file is not a column
  auto* seg = c->add_option("--segments", o->segments, "Number of Welch segments (default 8)")
                  ->check(CLI::PositiveNumber);
  c->add_option("--segment-length", o->segment_length, "Samples per segment")
      ->check(CLI::PositiveNumber)
      ->excludes(seg);
  c->add_option("--overlap", o->overlap, "Fraction of a segment shared with the next, [0, 1)");
  c->add_option("--out", o->out, "Output folder");
  c->add_flag("!--no-plot", o->plot, "Do not make the PNG plot");
  action = [o] { return run(*o); };
  return c;
}

}  // namespace valsalva::app
