#include "analysis/run_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace valsalva::analysis {

namespace {

std::vector<int> covered_nodes(const mesh::LocalMesh& local, const mesh::Mesh& mesh,
                               const mesh::DualMetrics& metrics, const StatisticsOptions& s) {
  switch (s.region) {
    case StatisticsOptions::Region::plane:
      return nodes_near_plane(local, s.a, s.b.normalized(), s.half_thickness);
    case StatisticsOptions::Region::box:
      return nodes_in_box(local, s.a, s.b);
    case StatisticsOptions::Region::section:
      return nodes_of_cut_cells(local, mesh, metrics, s.a, s.b, s.lo, s.hi);
    case StatisticsOptions::Region::all:
    case StatisticsOptions::Region::line:
      break;
  }
  return all_owned_nodes(local);
}

bool every(std::int64_t step, int n) {
  return step % n == 0;
}

}  // namespace

RunAnalysis::RunAnalysis(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
                         const mesh::LocalMesh& local, AnalysisOptions options, double density,
                         double dynamic_viscosity, std::filesystem::path run_dir, bool append)
    : mesh_(&mesh),
      metrics_(&metrics),
      local_(&local),
      options_(std::move(options)),
      dir_(std::move(run_dir)) {
  const bool root = local.comm.root();
  if (!options_.probes.points.empty()) {
    probes_ = std::make_unique<Probes>(mesh, metrics, local, options_.probes.points);
    probe_csv_.emplace(dir_ / "probes.csv", *probes_, std::vector<std::string>{"u", "v", "w", "p"},
                       append);
  }
  if (!options_.samples.empty() && root) std::filesystem::create_directories(dir_ / "samples");
  for (const auto& s : options_.samples) samples_.emplace_back(mesh, metrics, local, s);
  for (const auto& s : options_.statistics) {
    next_write_.push_back(NAN);
    if (s.region == StatisticsOptions::Region::line) {
      slot_.push_back(lines_.size());
      lines_.emplace_back(mesh, metrics, local, s.phase, s.line, "statistics." + s.phase.name);
      if (root && lines_.back().outside() > 0)
        fmt::print("statistics.{}: {} of the line's {} points are outside the mesh, left out\n",
                   s.phase.name, lines_.back().outside(), s.line.points);
      continue;
    }
    slot_.push_back(statistics_.size());
    auto nodes = covered_nodes(local, mesh, metrics, s);
    const auto covered = local.comm.sum(static_cast<std::int64_t>(nodes.size()));
    if (covered == 0)
      throw std::runtime_error(
          fmt::format("statistics.{}: the region covers no mesh node", s.phase.name));
    statistics_.emplace_back(local, s.phase, std::move(nodes));
  }
  if (!options_.wall_shear.patches.empty())
    wall_shear_.emplace(local, options_.wall_shear, density, dynamic_viscosity, dir_, append);
  for (const auto& d : options_.pressure_drops)
    drops_.push_back(
        {d, RegionMean(local, d.upstream, d.radius, "pressure_drop." + d.name + ".upstream"),
         RegionMean(local, d.downstream, d.radius, "pressure_drop." + d.name + ".downstream")});
  if (!drops_.empty() && root) {
    const auto path = dir_ / "pressure_drop.csv";
    drop_csv_.open(path, append ? std::ios::app : std::ios::trunc);
    if (!drop_csv_) throw std::runtime_error("pressure_drop: cannot write " + path.string());
    if (!append) {
      drop_csv_ << "time";
      for (const auto& d : drops_)
        drop_csv_ << fmt::format(",{0}_upstream,{0}_downstream,{0}_mmHg", d.options.name);
      drop_csv_ << '\n';
    }
  }
  for (const auto& o : options_.sections.sections) {
    sections_.emplace_back(local, o);
    if (root)
      fmt::print("section {}: {} mesh edges cut, dual faces projected on the plane {:.6e} m2\n",
                 o.name, sections_.back().edges(), sections_.back().projected_area());
  }
  if (!sections_.empty() && root) {
    const auto path = dir_ / "sections.csv";
    section_csv_.open(path, append ? std::ios::app : std::ios::trunc);
    if (!section_csv_) throw std::runtime_error("section: cannot write " + path.string());
    if (!append) {
      section_csv_ << "time";
      for (const auto& o : options_.sections.sections) section_csv_ << ',' << o.name << "_flux";
      section_csv_ << '\n' << std::flush;
    }
  }
}

void RunAnalysis::sample(const flow::FlowState& state, std::int64_t step,
                         const flow::EdgeField& face_flux) {
  if (!sections_.empty() && every(step, options_.sections.every_steps))
    sample_sections(state, face_flux);
  if (probes_ && every(step, options_.probes.every_steps))
    probe_csv_->append(state.time, probes_->sample(state));
  for (auto& s : samples_)
    if (s.due(state.time)) s.write(state, step, dir_ / "samples");
  // The initial state is no sample of the statistics (it is not a solution of the flow yet).
  for (std::size_t i = 0; i < options_.statistics.size(); ++i) {
    if (step > 0 && every(step, options_.statistics[i].every_steps)) {
      if (options_.statistics[i].region == StatisticsOptions::Region::line)
        lines_[slot_[i]].add(state);
      else
        statistics_[slot_[i]].add(state.time, state.velocity, state.pressure);
    }
    write_interim(i, state.time);
  }
  if (wall_shear_ && every(step, options_.wall_shear.every_steps)) wall_shear_->sample(state);
  bool any = false;
  for (const auto& d : drops_) any = any || every(step, d.options.every_steps);
  if (!any) return;
  // RegionMean is collective: every rank evaluates, rank 0 writes the row.
  std::string row = fmt::format("{:.17g}", state.time);
  for (const auto& d : drops_) {
    if (!every(step, d.options.every_steps)) {
      row += ",,,";
      continue;
    }
    const PressureDrop p{d.upstream(state.pressure), d.downstream(state.pressure)};
    row += fmt::format(",{:.9e},{:.9e},{:.9e}", p.upstream, p.downstream, p.mmhg());
  }
  if (drop_csv_.is_open()) drop_csv_ << row << '\n' << std::flush;
}

std::vector<io::CheckpointArray> RunAnalysis::checkpoint_arrays() const {
  std::vector<io::CheckpointArray> out;
  for (const auto& s : statistics_)
    for (auto& a : s.checkpoint_arrays()) out.push_back(std::move(a));
  for (const auto& s : lines_)
    for (auto& a : s.checkpoint_arrays()) out.push_back(std::move(a));
  if (wall_shear_)
    for (auto& a : wall_shear_->checkpoint_arrays()) out.push_back(std::move(a));
  return out;
}

void RunAnalysis::restore(const io::CheckpointReader& reader) {
  for (auto& s : statistics_) s.restore(reader);
  for (auto& s : lines_) s.restore(reader);
  if (wall_shear_) wall_shear_->restore(reader);
}

// Interim statistics files at start_time + k write_interval (the first such time after the
// run's first sample, so a restarted run continues the sequence), overwritten by later writes.
void RunAnalysis::write_interim(std::size_t i, double time) {
  const double interval = options_.statistics[i].write_interval;
  if (!(interval > 0)) return;
  const double start = options_.statistics[i].phase.start_time;
  const double eps = 1e-9 * interval;
  auto next_after = [&](double t) {
    return start + interval * (std::floor((std::max(t, start) - start) / interval + eps) + 1);
  };
  if (std::isnan(next_write_[i])) next_write_[i] = next_after(time);
  if (time < next_write_[i] - eps) return;
  write_statistics(i);
  next_write_[i] = next_after(time);
}

void RunAnalysis::write_statistics(std::size_t i) const {
  if (options_.statistics[i].region == StatisticsOptions::Region::line)
    lines_[slot_[i]].write(dir_ / "statistics");
  else
    statistics_[slot_[i]].write(*mesh_, *metrics_, dir_ / "statistics");
}

// One row of sections.csv; every rank evaluates (SectionFlux::flux is collective).
void RunAnalysis::sample_sections(const flow::FlowState& state, const flow::EdgeField& face_flux) {
  const flow::EdgeField* flux = &face_flux;
  if (face_flux.empty()) {
    flow::central_face_flux(*local_, state.velocity, central_flux_);
    flux = &central_flux_;
  }
  std::string row = fmt::format("{:.17g}", state.time);
  last_sections_ = fmt::format("t = {:.9g} s:", state.time);
  for (const auto& s : sections_) {
    const double q = s.flux(*flux);
    row += fmt::format(",{:.17g}", q);
    last_sections_ += fmt::format(" {} {:.9e} m3/s", s.options().name, q);
  }
  if (section_csv_.is_open()) section_csv_ << row << '\n' << std::flush;
}

void RunAnalysis::finish() const {
  for (std::size_t i = 0; i < options_.statistics.size(); ++i) write_statistics(i);
  if (wall_shear_) wall_shear_->write(*mesh_, *metrics_, dir_);
  if (local_->comm.root() && !last_sections_.empty())
    fmt::print("section fluxes at {}\n", last_sections_);
}

}  // namespace valsalva::analysis
