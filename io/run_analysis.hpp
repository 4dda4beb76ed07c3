// Everything a run measures while it runs, assembled from the scene's analysis sections
// (io/analysis_options.hpp): probes, line and plane samples, phase statistics, wall shear
// stress with TAWSS/OSI, pressure differences. Only what the scene asks for is built; the run
// loop calls sample() after every step (flow::RunHooks::after_step), the checkpoint hook saves
// checkpoint_arrays(), a restart calls restore(), and finish() writes the end-of-run files.
// Files in the run directory:
//   probes.csv          time, <probe>_u, _v, _w, _p           (every probes.every_steps)
//   samples/            <sample>_<step>.csv                   (io/line_plane_samples.hpp)
//   statistics/         <name>.xmf + .h5, <name>_phases.csv   (io/phase_statistics.hpp)
//   wall_shear*.csv     (io/wall_shear_recorder.hpp)
//   pressure_drop.csv   time, <name>_upstream, <name>_downstream (Pa), <name>_mmHg
// A restart in place appends to the CSV time series.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "io/analysis_options.hpp"
#include "io/checkpoint.hpp"
#include "io/line_plane_samples.hpp"
#include "io/phase_statistics.hpp"
#include "io/pressure_drop.hpp"
#include "io/probes.hpp"
#include "io/wall_shear_recorder.hpp"

namespace valsalva::io {

class RunAnalysis {
 public:
  // Collective. `append`: continue the CSV series of an earlier run in the same directory.
  // Throws std::runtime_error naming the probe, sample or region that cannot be placed.
  RunAnalysis(const flow::Mesh& mesh, const flow::DualMetrics& metrics,
              const flow::LocalMesh& local, AnalysisOptions options, double density,
              double dynamic_viscosity, std::filesystem::path run_dir, bool append);

  bool empty() const { return options_.empty(); }
  // Collective: the samples due after step `step` (step 0 = the initial state).
  void sample(const flow::FlowState& state, std::int64_t step);
  std::vector<CheckpointArray> checkpoint_arrays() const;
  // Collective: statistics and wall shear accumulators from a checkpoint of the same scene.
  void restore(const CheckpointReader& reader);
  // Collective: statistics and wall shear files.
  void finish() const;

  const std::vector<PhaseStatistics>& statistics() const { return statistics_; }
  const WallShearRecorder* wall_shear() const { return wall_shear_ ? &*wall_shear_ : nullptr; }

 private:
  void write_interim(std::size_t statistics, double time);
  struct Drop {
    PressureDropOptions options;
    RegionMean upstream, downstream;
  };
  const flow::Mesh* mesh_;
  const flow::DualMetrics* metrics_;
  const flow::LocalMesh* local_;
  AnalysisOptions options_;
  std::filesystem::path dir_;
  std::unique_ptr<Probes> probes_;
  std::optional<ProbeCsv> probe_csv_;
  std::vector<LinePlaneSamples> samples_;
  std::vector<PhaseStatistics> statistics_;
  std::vector<double> next_write_;  // per statistics: next interim write time (NaN: not set)
  std::optional<WallShearRecorder> wall_shear_;
  std::vector<Drop> drops_;
  std::ofstream drop_csv_;
};

}  // namespace valsalva::io
