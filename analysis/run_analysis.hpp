// Everything a run measures while it runs, assembled from the scene's analysis sections
// (analysis/analysis_options.hpp): probes, line and plane samples, phase statistics on regions and
// lines, wall shear stress with TAWSS/OSI, pressure differences, section fluxes. Only what the
// scene asks for is built; the run loop calls sample() after every step
// (run::RunHooks::after_step), the checkpoint hook saves checkpoint_arrays(), a restart calls
// restore(), and finish() writes the end-of-run files. Files in the run directory:
//   probes.csv          time, <probe>_u, _v, _w, _p           (every probes.every_steps)
//   samples/            <sample>_<step>.csv                   (analysis/line_plane_samples.hpp)
//   statistics/         <name>.xmf + .h5, <name>_phases.csv   (analysis/phase_statistics.hpp)
//                       <name>.csv for a line                 (analysis/line_statistics.hpp)
//   wall_shear*.csv     (analysis/wall_shear_recorder.hpp)
//   pressure_drop.csv   time, <name>_upstream, <name>_downstream (Pa), <name>_mmHg
//   sections.csv        time, <name>_flux (m^3/s)             (analysis/section_flux.hpp)
// A restart in place appends to the CSV time series.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/analysis_options.hpp"
#include "analysis/line_plane_samples.hpp"
#include "analysis/line_statistics.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/pressure_drop.hpp"
#include "analysis/probes.hpp"
#include "analysis/section_flux.hpp"
#include "analysis/wall_shear_recorder.hpp"
#include "io/checkpoint.hpp"

namespace valsalva::analysis {

class RunAnalysis {
 public:
  // Collective. `append`: continue the CSV series of an earlier run in the same directory.
  // Throws std::runtime_error naming the probe, sample or region that cannot be placed.
  RunAnalysis(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
              const mesh::LocalMesh& local, AnalysisOptions options, double density,
              double dynamic_viscosity, std::filesystem::path run_dir, bool append);

  bool empty() const { return options_.empty(); }
  // Collective: the samples due after step `step` (step 0 = the initial state). `face_flux`:
  // the projected face flux of the state on every local edge (run::RunLoop::face_flux()),
  // which the section fluxes sum; empty (the initial state, before any projection): the
  // sections use the central face flux of the nodal velocity instead.
  void sample(const flow::FlowState& state, std::int64_t step,
              const flow::EdgeField& face_flux = {});
  std::vector<io::CheckpointArray> checkpoint_arrays() const;
  // Collective: statistics and wall shear accumulators from a checkpoint of the same scene.
  void restore(const io::CheckpointReader& reader);
  // Collective: statistics and wall shear files; rank 0 prints the last section fluxes.
  void finish() const;

  const std::vector<PhaseStatistics>& statistics() const { return statistics_; }
  const WallShearRecorder* wall_shear() const { return wall_shear_ ? &*wall_shear_ : nullptr; }
  // The prescribed body-force density of the run, for the wall shear stress (see
  // WallShearRecorder::set_body_force); must outlive the analysis.
  // A non-Newtonian fluid: the wall shear stress with its nodal viscosity
  // (WallShearRecorder::set_viscosity_model).
  void set_viscosity_model(const flow::ViscosityModel& model) {
    if (wall_shear_) wall_shear_->set_viscosity_model(model);
  }
  void set_body_force(const flow::VectorField* force_density) {
    if (wall_shear_) wall_shear_->set_body_force(force_density);
  }
  // The immersed structures' kernel support at a sampled state, for the wall shear stress (see
  // WallShearRecorder::set_support_nodes).
  void set_support_nodes(WallShearRecorder::NodeMask source) {
    if (wall_shear_) wall_shear_->set_support_nodes(std::move(source));
  }

 private:
  void write_interim(std::size_t statistics, double time);
  void write_statistics(std::size_t statistics) const;
  void sample_sections(const flow::FlowState& state, const flow::EdgeField& face_flux);
  struct Drop {
    PressureDropOptions options;
    RegionMean upstream, downstream;
  };
  const mesh::Mesh* mesh_;
  const mesh::DualMetrics* metrics_;
  const mesh::LocalMesh* local_;
  AnalysisOptions options_;
  std::filesystem::path dir_;
  std::unique_ptr<Probes> probes_;
  std::optional<ProbeCsv> probe_csv_;
  std::vector<LinePlaneSamples> samples_;
  std::vector<PhaseStatistics> statistics_;
  std::vector<LineStatistics> lines_;
  std::vector<std::size_t> slot_;   // per statistics option: index into statistics_ or lines_
  std::vector<double> next_write_;  // per statistics: next interim write time (NaN: not set)
  std::optional<WallShearRecorder> wall_shear_;
  std::vector<Drop> drops_;
  std::ofstream drop_csv_;
  std::vector<SectionFlux> sections_;
  std::ofstream section_csv_;
  flow::EdgeField central_flux_;
  std::string last_sections_;  // the newest section fluxes, for the end-of-run message
};

}  // namespace valsalva::analysis
