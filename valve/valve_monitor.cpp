#include "valve/valve_monitor.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "flow/patch_fluxes.hpp"
#include "io/appended_series.hpp"
#include "io/hdf5_file.hpp"
#include "structure/contact.hpp"
#include "structure/leaflet_indices.hpp"
#include "structure/orifice_area.hpp"
#include "valve/leaflet_mesh.hpp"

namespace valsalva::valve {

namespace {

constexpr const char* samples_array = "valve_cycle_samples";

// The free-edge node farthest from both ends of the edge (the nodes it shares with the
// attachment), in the reference configuration: the tip of an open or a closed leaflet.
int free_edge_midpoint(const structure::SolidMesh& m, const std::string& prefix) {
  const auto& edge = m.node_set(prefix + "_free_edge");
  const auto& attached = m.node_set(prefix + "_attachment");
  std::vector<int> ends;
  for (int n : edge)
    if (std::find(attached.begin(), attached.end(), n) != attached.end()) ends.push_back(n);
  int best = edge.front();
  double best_distance = -1;
  for (int n : edge) {
    double nearest_end = std::numeric_limits<double>::infinity();
    for (int e : ends) nearest_end = std::min(nearest_end, (m.X.col(n) - m.X.col(e)).norm());
    if (ends.empty()) nearest_end = 0;
    if (nearest_end > best_distance) best = n, best_distance = nearest_end;
  }
  return best;
}

analysis::RegionMean region(const mesh::LocalMesh& local, const Eigen::Vector3d& c, double r,
                            const char* key) {
  return analysis::RegionMean(local, c, r, fmt::format("valve.{}", key));
}

}  // namespace

ValveMonitor::ValveMonitor(const mesh::LocalMesh& local, const ibm::ImmersedStructure& structure,
                           int body, analysis::ValveMonitorOptions options,
                           const std::filesystem::path& run_dir, bool append)
    : local_(&local),
      structure_(&structure),
      body_(body),
      options_(std::move(options)),
      upstream_(region(local, options_.tpg_upstream, options_.tpg_radius, "tpg_upstream")),
      downstream_(region(local, options_.tpg_downstream, options_.tpg_radius, "tpg_downstream")),
      cycles_({options_.period, options_.start_time, options_.open_fraction, 0.9}),
      cycles_path_(run_dir / "valve_cycles.csv"),
      append_(append) {
  const structure::SolidMesh& all = structure.body(body).mesh();
  for (int i = 1; i <= 3; ++i) {
    const std::string prefix = fmt::format("leaflet{}", i);
    for (const std::string& set : {prefix, prefix + "_free_edge", prefix + "_attachment"})
      if (!all.node_sets.count(set) || all.node_sets.at(set).empty())
        throw std::runtime_error(fmt::format(
            "valve.structure = '{}': its mesh has no node set '{}' (a valve needs leaflet1..3 "
            "with _free_edge and _attachment, as `valsalva make-valve` writes them)",
            options_.structure, set));
    Leaflet l;
    l.mesh = leaflet_submesh(all, i);
    l.nodes = all.node_set(prefix);
    l.tip = free_edge_midpoint(all, prefix);
    leaflets_.push_back(std::move(l));
  }
  for (std::size_t p = 0; p < local.patch_names.size(); ++p) {
    if (local.patch_names[p] == options_.inlet_patch) inlet_ = static_cast<int>(p);
    if (local.patch_names[p] == options_.outlet_patch) outlet_ = static_cast<int>(p);
  }
  if (!local.comm.root()) return;
  auto open = [&](std::ofstream& f, const std::string& name, const std::string& header) {
    const auto path = run_dir / name;
    f.open(path, append ? std::ios::app : std::ios::trunc);
    if (!f) throw std::runtime_error("valve: cannot write " + path.string());
    if (!append) f << header << '\n';
  };
  std::string header =
      "step,time,cycle,inlet_flow,outlet_flow,tpg_mmHg,orifice_area,orifice_raster_error,"
      "opening_ratio";
  for (int i = 1; i <= 3; ++i) header += fmt::format(",tip{0}_x,tip{0}_y,tip{0}_z,tip{0}_r", i);
  header +=
      ",max_von_mises,max_von_mises_element,max_von_mises_x,max_von_mises_y,max_von_mises_z,"
      "min_gap,contact_area";
  open(csv_, "valve.csv", header);
  open(cycles_csv_, "valve_cycles.csv",
       "cycle,start,end,samples,tpg_max_mmHg,tpg_min_mmHg,forward_volume,regurgitant_volume,"
       "closing_volume,leakage_volume,max_opening_ratio,min_opening_ratio,opening_start,fully_open,"
       "closing,max_von_mises");
}

void ValveMonitor::sample(const flow::FlowState& state, std::int64_t step) {
  // Every every_steps, and on each cycle boundary the run lands on (time.end = k periods, output
  // times): without it a run whose last step is not a multiple of every_steps never closes its
  // last cycle, and valve_cycles.csv stays empty.
  const double cycles = (state.time - options_.start_time) / options_.period;
  const bool on_boundary = step > 0 && std::abs(cycles - std::round(cycles)) < 1e-9;
  if (step % options_.every_steps != 0 && !on_boundary) return;
  // Collective parts first, on every rank; the leaflets are replicated.
  const auto fluxes = flow::patch_fluxes(*local_, state.velocity);
  const double inflow = -fluxes[inlet_], outflow = fluxes[outlet_];
  const double tpg =
      (upstream_(state.pressure) - downstream_(state.pressure)) / analysis::pascal_per_mmhg;
  if (!local_->comm.root()) return;

  const Eigen::Matrix3Xd x = structure_->body_positions(body_);
  const ibm::ImmersedBody& body = structure_->body(body_);
  std::vector<Eigen::Matrix3Xd> own(3);
  std::vector<structure::LeafletPositions> parts;
  for (std::size_t i = 0; i < leaflets_.size(); ++i) {
    own[i].resize(3, static_cast<long>(leaflets_[i].nodes.size()));
    for (std::size_t k = 0; k < leaflets_[i].nodes.size(); ++k)
      own[i].col(static_cast<long>(k)) = x.col(leaflets_[i].nodes[k]);
    parts.push_back({&leaflets_[i].mesh, &own[i]});
  }
  structure::ValveFrame frame{options_.axis_point, options_.axis, options_.annulus_radius};
  structure::OrificeOptions orifice_options;
  orifice_options.rings = options_.orifice_rings;
  const auto orifice = structure::geometric_orifice_area(parts, frame, orifice_options);
  const auto basis = structure::valve_basis(frame);
  const auto stress = structure::von_mises_summary(body.solid_forces(), x, 99);
  const auto contact = body.contact_summary(x);

  std::string row = fmt::format("{},{:.17g},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.3e},{:.9e}", step,
                                state.time, cycles_.cycle_of(state.time), inflow, outflow, tpg,
                                orifice.area, orifice.raster_error, orifice.opening_ratio);
  for (const auto& l : leaflets_) {
    const Eigen::Vector3d p = x.col(l.tip), local = basis.to_local(p);
    row += fmt::format(",{:.9e},{:.9e},{:.9e},{:.9e}", p.x(), p.y(), p.z(),
                       std::hypot(local.x(), local.y()));
  }
  const Eigen::Vector3d& at = stress.max_position;
  row += fmt::format(
      ",{:.9e},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}", stress.max, stress.max_element, at.x(),
      at.y(), at.z(),
      body.has_contact() && std::isfinite(contact.min_gap) ? contact.min_gap : std::nan(""),
      contact.area);
  csv_ << row << '\n' << std::flush;

  const auto done = cycles_.add({state.time, inflow, tpg, orifice.opening_ratio, stress.max});
  if (done)
    cycles_csv_ << fmt::format(
                       "{},{:.9g},{:.9g},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
                       "{:.6e},{:.6g},{:.6g},{:.6g},{:.6e}\n",
                       done->cycle, done->start, done->end, done->samples, done->tpg_max,
                       done->tpg_min, done->forward_volume, done->regurgitant_volume,
                       done->closing_volume, done->leakage_volume, done->max_opening_ratio,
                       done->min_opening_ratio, done->opening_start, done->fully_open,
                       done->closing, done->max_von_mises)
                << std::flush;
}

std::vector<io::CheckpointArray> ValveMonitor::checkpoint_arrays() const {
  // Row 0: the number of samples; then one row per sample of the open cycle (rank 0's copy:
  // only rank 0 tracks the cycles).
  io::CheckpointArray a{samples_array, 0, analysis::valve_sample_fields, {}, {}};
  const auto flat = cycles_.state();
  const auto n = static_cast<std::int64_t>(flat.size() / analysis::valve_sample_fields);
  a.global_rows = 1 + local_->comm.max(n);
  if (local_->comm.root()) {
    for (std::int64_t r = 0; r <= n; ++r) a.rows.push_back(r);
    a.data.assign(analysis::valve_sample_fields, 0.0);
    a.data[0] = static_cast<double>(n);
    a.data.insert(a.data.end(), flat.begin(), flat.end());
  }
  return {a};
}

void ValveMonitor::restore(const io::CheckpointReader& reader) {
  if (!reader.has(samples_array)) return;  // a checkpoint of a run without [valve]
  const auto [rows, cols] = reader.shape(samples_array);
  std::vector<std::int64_t> all(static_cast<std::size_t>(rows));
  for (std::int64_t r = 0; r < rows; ++r) all[static_cast<std::size_t>(r)] = r;
  const auto data = reader.read_array(samples_array, all);
  if (cols != analysis::valve_sample_fields || data.empty() ||
      static_cast<std::int64_t>(data[0]) != rows - 1)
    throw std::runtime_error("restart: the checkpoint's valve cycle samples are malformed");
  std::string error;
  if (local_->comm.root()) {
    try {
      cycles_.restore(std::span(data).subspan(analysis::valve_sample_fields));
      if (append_) cut_cycles_csv();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  io::h5::settle(local_->comm.get(), error);
}

void ValveMonitor::cut_cycles_csv() {
  // Rows of cycles completed after the checkpoint would be written again: keep those before the
  // open cycle (none when no cycle has begun). The cycle is an integer first column, cut as a
  // step column is.
  const auto& open = cycles_.open_samples();
  const int keep_below = open.empty() ? 0 : cycles_.cycle_of(open.front().time);
  cycles_csv_.close();
  if (const auto cut = io::truncate_series(cycles_path_, true, keep_below - 1, 0, 0); cut > 0)
    fmt::print("restart: {} rows of valve_cycles.csv after the checkpoint removed\n", cut);
  cycles_csv_.open(cycles_path_, std::ios::app);
  if (!cycles_csv_) throw std::runtime_error("valve: cannot write " + cycles_path_.string());
}

}  // namespace valsalva::valve
