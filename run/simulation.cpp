// A scene from its mesh to its results; see simulation.hpp.
#include "run/simulation.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

#include "analysis/run_analysis.hpp"
#include "analysis/section_flux.hpp"
#include "core/comm.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/halo_size.hpp"
#include "run/immersed_ghosts.hpp"
#include "run/immersed_run.hpp"
#include "run/phase.hpp"
#include "run/restart_continuity.hpp"
#include "run/run_directory.hpp"
#include "run/stop_signal.hpp"
#include "scene/mesh_source.hpp"
#include "scene/scene_cycle_period.hpp"
#include "scene/scene_keys_analysis.hpp"
#include "scene/scene_keys_boundary.hpp"
#include "scene/scene_keys_flow.hpp"
#include "scene/scene_keys_les.hpp"
#include "scene/scene_keys_partition.hpp"
#include "scene/scene_keys_structure.hpp"
#include "scene/scene_keys_valve.hpp"
#include "valve/valve_monitor.hpp"

namespace valsalva::run {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The checkpoint to restart from: a file, or the newest in <dir>/checkpoints for "latest".
std::optional<fs::path> restart_checkpoint(const std::string& restart, const fs::path& dir) {
  if (restart.empty()) return std::nullopt;
  if (restart == "latest") {
    auto latest = io::latest_checkpoint(dir / "checkpoints");
    if (!latest)
      throw std::runtime_error(
          fmt::format("--restart latest: no checkpoint in {}", (dir / "checkpoints").string()));
    return latest;
  }
  if (!fs::is_regular_file(restart))
    throw std::runtime_error(fmt::format("--restart {}: no such file", restart));
  return fs::path(restart);
}

// The period shown as cycle and phase: the first phase-averaged statistics, else the first
// periodic inlet waveform; 0 when the run has none.
double cycle_period(const analysis::AnalysisOptions& analysis,
                    const std::vector<flow::BoundarySpec>& boundary) {
  for (const auto& s : analysis.statistics)
    if (s.phase.period > 0) return s.phase.period;
  for (const auto& b : boundary)
    if (b.type == flow::BoundaryType::inlet && b.flow_rate.kind != flow::Waveform::Kind::constant)
      return b.flow_rate.period;
  return 0;
}

scene::Progress progress_mode(const scene::Scene& scene, bool quiet) {
  const auto mode = scene.get<std::string>("run.progress");
  if (quiet || mode == "quiet") return scene::Progress::quiet;
  if (mode == "lines") return scene::Progress::lines;
  if (mode == "status") return scene::Progress::status;
  // Open MPI hands its processes a pseudo-terminal even when mpiexec's own output goes to a
  // file, so under mpiexec (OMPI_COMM_WORLD_SIZE, PMI_SIZE) "auto" keeps plain lines.
  const bool mpiexec = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE");
  return isatty(fileno(stdout)) && !mpiexec ? scene::Progress::status : scene::Progress::lines;
}

}  // namespace

struct Simulation::Parts {
  Parts(const scene::Scene& s, MPI_Comm c) : scene(s), comm(c) { MPI_Comm_rank(comm, &rank); }

  scene::Scene scene;
  MPI_Comm comm;
  int rank = 0;
  bool print = true;
  fs::path run_path;
  bool in_place = false;
  std::optional<fs::path> checkpoint;
  mesh::Mesh mesh;
  mesh::DualMetrics metrics;
  mesh::LocalMesh local;
  mesh::PartitionOptions partition;
  mesh::GhostRegion ghosts;  // near the immersed structures
  scene::LesSetup les;
  std::optional<analysis::RunAnalysis> analysis;
  std::optional<run::ImmersedRun> immersed;
  std::optional<valve::ValveMonitor> valve_monitor;
  std::map<std::string, std::unique_ptr<io::FieldOutput>> outputs;
  std::string fields_name = "fields";
  std::optional<run::RunLoop> loop;
  std::uint64_t mesh_hash = 0;
  std::optional<io::CheckpointWriter> writer;
  std::optional<run::StopSignal> stop;
  fs::path last_checkpoint;
  Clock::time_point t0 = Clock::now(), last_write = Clock::now();
  StepObserver observer;
  VelocityModifier modifier;
  bool stop_requested = false;  // by the observer
  bool stopped_by_signal = false;

  void write_fields(const std::string& stream, double time, const io::FieldSet& set);
  void write_checkpoint(const flow::FlowState& state, std::int64_t step, double dt,
                        run::RunHooks::Moment moment);
  void print_summary(const scene::Scene& scene, double rho, double viscosity) const;
};

// Fields go to <basename>.xmf/.h5 in the run directory: "fields" at the output interval,
// "last_good" when the run stops on a bad state. FieldOutput is collective; the run loop calls
// the sink on every rank. Continuing in place must not replace the earlier fields: they get a
// name of their own (fields_name).
void Simulation::Parts::write_fields(const std::string& stream, double time,
                                     const io::FieldSet& set) {
  const std::string basename = stream == "fields" ? fields_name : stream;
  auto& o = outputs[basename];
  if (!o) o = std::make_unique<io::FieldOutput>(mesh, metrics, local, run_path, basename);
  std::vector<io::FieldOutput::Scalar> scalars;
  std::vector<io::FieldOutput::Vector> vectors;
  io::FieldSet all = set;
  static const std::vector<analysis::PhaseStatistics> no_statistics;
  les.add_fields(all, time, *set.state_velocity, analysis ? analysis->statistics() : no_statistics);
  if (immersed && stream == "fields") immersed->write(time, all);  // + the Lagrangian meshes
  for (const auto& [name, f] : all.scalars) scalars.push_back({name, f});
  for (const auto& [name, f] : all.vectors) vectors.push_back({name, f});
  o->write(time, scalars, vectors);
}

// Checkpoints every N steps, every M wall-clock minutes (rank 0's clock decides, so that all
// ranks agree) and on SIGINT/SIGTERM; the newest output.checkpoint_keep are kept. They carry the
// Poisson warm start, the face flux, nu_sgs, the lumped outlets' states and the analysis
// accumulators.
void Simulation::Parts::write_checkpoint(const flow::FlowState& state, std::int64_t step, double dt,
                                         run::RunHooks::Moment moment) {
  using Moment = run::RunHooks::Moment;
  const auto every_steps =
      static_cast<std::int64_t>(scene.get<int>("output.checkpoint_every_steps"));
  const double every_seconds = 60 * scene.get<double>("output.checkpoint_every_minutes");
  const bool periodic = every_steps > 0 || every_seconds > 0;
  bool due = moment == Moment::stopping || (moment == Moment::finished && periodic) ||
             (every_steps > 0 && step % every_steps == 0);
  if (every_seconds > 0) {
    int late = seconds_since(last_write) >= every_seconds ? 1 : 0;
    core::Comm(comm).broadcast(late);
    due = due || late != 0;
  }
  if (!due) return;
  std::vector<io::CheckpointArray> extras;
  if (analysis) extras = analysis->checkpoint_arrays();
  if (immersed)
    for (auto& a : immersed->checkpoint_arrays()) extras.push_back(std::move(a));
  if (valve_monitor)
    for (auto& a : valve_monitor->checkpoint_arrays()) extras.push_back(std::move(a));
  extras.push_back(
      io::nodal_checkpoint_array("pressure_increment", local, loop->pressure_increment()));
  if (!loop->face_flux().empty())
    extras.push_back(io::edge_checkpoint_array("face_flux", local, loop->face_flux()));
  if (!loop->subgrid_viscosity().empty())
    extras.push_back(
        io::nodal_checkpoint_array("subgrid_viscosity", local, loop->subgrid_viscosity()));
  if (const auto* lumped = loop->solver().lumped_outlets())
    extras.push_back(io::replicated_checkpoint_array("lumped_outlets", local, lumped->saved()));
  if (const auto forcing = loop->forcing_state(); !forcing.empty())
    extras.push_back(io::replicated_checkpoint_array("flow_rate_control", local, forcing));
  last_checkpoint = writer->write(state, step, dt, extras);
  last_write = Clock::now();
}

void Simulation::Parts::print_summary(const scene::Scene& s, double rho, double viscosity) const {
  const mesh::HaloSize halo = mesh::halo_size(local);  // collective
  if (rank != 0 || !print) return;
  fmt::print(
      "mesh: {} nodes ({} dual nodes), {} cells; partition: {} ranks, {} ghost layers{}, "
      "method {}\n",
      mesh.num_nodes(), metrics.num_nodes(), mesh.num_cells(), local.comm.size(),
      partition.ghost_layers,
      ghosts.distance > 0 ? fmt::format(" (near the structures: {:.3g} m, deepest layer {})",
                                        ghosts.distance, halo.deepest_layer)
                          : "",
      mesh::to_string(partition.method));
  if (local.comm.size() > 1)
    fmt::print(
        "halo: owned nodes per rank {}..{}; per rank at most {} ghost nodes, {} neighbours, {} "
        "values sent per scalar exchange\n",
        halo.owned_min, halo.owned_max, halo.ghosts_max, halo.neighbours_max, halo.sent_max);
  const auto law = s.get<std::string>("flow.viscosity_model");
  fmt::print("flow: rho {:.6g} kg/m3, {}, scheme {}, initial state {}\n", rho,
             law == "newtonian" ? fmt::format("nu {:.6g} m2/s", viscosity)
                                : fmt::format("viscosity model {}", law),
             s.get<std::string>("flow.scheme"), s.get<std::string>("initial.type"));
  if (les.subgrid_viscosity)
    fmt::print("les: model {}, constant {:.4g}\n", les::to_string(les.model), les.constant);
  if (immersed) {
    const auto& ib = immersed->structure();
    const auto& o = ib.options();
    fmt::print(
        "immersed: {} structure(s), {} markers, kernel {} width {} h, coupling {}, dt bound "
        "{:.4e} s (dt_safety {})\n",
        ib.num_bodies(), ib.num_markers(), ibm::kernel_name(o.transfer.kernel.type),
        o.transfer.kernel.width, ibm::coupling_name(o.mode), immersed->dt_bound(),
        o.stability_safety);
  }
}

Simulation::Simulation(const scene::Scene& scene_in, const RunRequest& request, MPI_Comm comm)
    : parts_(std::make_unique<Parts>(scene_in, comm)) {
  auto& p = *parts_;
  const auto& scene = p.scene;
  p.print = request.print;
  Phase phase("setting up the run of " + scene.file().string());
  const auto dir = request.out.empty() ? run::default_run_path(scene) : request.out;
  const bool wipe = request.overwrite || scene.get<bool>("run.overwrite");
  // A restart continues in the run directory of the checkpoint when it is that directory (or
  // "latest"): nothing there is deleted, the logs are appended to and the fields go to a new
  // fields_restart_<step>.xmf. Otherwise (a checkpoint from elsewhere) the run directory is
  // prepared as for a new run, with the same --overwrite promise.
  p.checkpoint = restart_checkpoint(request.restart, dir);
  p.in_place =
      p.checkpoint && fs::exists(dir / run::RunDirectory::resolved_scene_name) &&
      fs::equivalent(fs::absolute(*p.checkpoint).parent_path(), fs::absolute(dir / "checkpoints"));
  if (p.in_place && wipe)
    throw std::runtime_error(fmt::format(
        "--restart {} with --overwrite (or run.overwrite) would delete the checkpoint with the "
        "run directory {}: drop --overwrite to continue there, or give another --out",
        p.checkpoint->string(), dir.string()));
  if (p.in_place)
    if (const auto change =
            run::restart_scene_change(dir / run::RunDirectory::resolved_scene_name, scene);
        !change.empty())
      throw std::runtime_error(change);

  // Everything the scene can get wrong is checked before the run directory is touched.
  phase.next(mesh_phase(scene));
  p.mesh = scene::build_mesh(scene, comm);
  phase.next(fmt::format("computing the dual metrics of the mesh ({} nodes, {} cells)",
                         p.mesh.num_nodes(), p.mesh.num_cells()));
  p.metrics = mesh::compute_dual_metrics(p.mesh);
  phase.next("checking the scene against the mesh");
  auto boundary = scene::read_boundary_conditions(scene, p.mesh);
  const auto analysis_options = scene::read_analysis_options(scene, p.mesh);
  auto immersed_setup = scene::read_immersed_setup(scene, p.mesh);
  const auto valve_options = scene::read_valve_monitor_options(scene, p.mesh);
  scene::check_les_scene(scene);
  scene::flow_run_options(scene, dir);  // its checks (time step, output volume), before any write
  scene::check_initial_state(scene, p.mesh);
  scene::check_forcing(scene, boundary);
  scene::check_cycle_periods(scene);
  scene::check_step_count(scene, p.metrics);
  p.run_path = dir;  // prepared below, once a checkpoint to restart from has been opened

  p.partition = scene::partition_options(scene);
  p.ghosts =
      marker_ghost_region(immersed_setup, p.metrics, scene.get<double>("partition.ghost_distance"));
  phase.next(fmt::format("partitioning the mesh ({} dual nodes, partition.method = {})",
                         p.metrics.num_nodes(), mesh::to_string(p.partition.method)));
  p.local = mesh::distribute(p.mesh, p.metrics, comm, p.partition, p.ghosts);
  phase.next(
      fmt::format("setting up the LES model, the analysis and the structures ({} local nodes)",
                  p.local.num_local()));

  auto run_options = scene::flow_run_options(scene, p.run_path);
  p.les = scene::les_setup(scene, p.local);  // nu_sgs/nu joins the fields with a model
  run_options.projection.subgrid_viscosity = p.les.subgrid_viscosity;
  run_options.output.progress = progress_mode(scene, request.quiet);
  run_options.output.print = request.print;
  run_options.output.cycle_period = cycle_period(analysis_options, boundary);
  const double rho = run_options.projection.density;
  const bool checkpoints = scene.get<int>("output.checkpoint_every_steps") > 0 ||
                           scene.get<double>("output.checkpoint_every_minutes") > 0 ||
                           scene.get<bool>("output.checkpoint_on_signal");
  if (p.checkpoint || checkpoints) p.mesh_hash = io::mesh_hash(p.mesh);
  std::optional<io::CheckpointReader> in;
  if (p.checkpoint) {
    in.emplace(p.local, p.mesh_hash, *p.checkpoint);  // throws on another mesh
    const double end = scene.get<double>("time.end");
    if (end < in->info().time * (1 - 1e-12))
      throw scene.error("time.end",
                        fmt::format("{:.9g} s is before the time of checkpoint '{}', {:.9g} s: "
                                    "nothing to continue",
                                    end, p.checkpoint->string(), in->info().time),
                        fmt::format(">= {:.9g}", in->info().time));
  }
  // A checkpoint of another mesh or time is refused before a new run directory is made.
  if (!p.in_place) run::RunDirectory::prepare(dir, wipe, scene, comm);
  if (in) {
    if (p.in_place) {
      std::vector<std::string> series{"log.csv"};
      if (!analysis_options.probes.points.empty()) series.push_back("probes.csv");
      if (!analysis_options.pressure_drops.empty()) series.push_back("pressure_drop.csv");
      if (!analysis_options.sections.sections.empty()) series.push_back("sections.csv");
      if (!analysis_options.wall_shear.patches.empty()) series.push_back("wall_shear_history.csv");
      if (!immersed_setup.empty()) series.push_back("structures.csv");
      if (valve_options) series.push_back("valve.csv");
      if (std::any_of(boundary.begin(), boundary.end(),
                      [](const flow::BoundarySpec& b) { return flow::lumped_type(b.type); }))
        series.push_back("outlets.csv");
      run::continue_in_place(p.run_path, scene, in->info().step, in->info().time, in->info().dt,
                             series, p.local.comm);
    }
  }
  if (!analysis_options.empty())
    p.analysis.emplace(p.mesh, p.metrics, p.local, analysis_options, rho,
                       rho * run_options.projection.viscosity, p.run_path, p.in_place);

  std::int64_t start_step = 0;
  flow::FlowState start;
  flow::ScalarField start_dp, start_nu_sgs;
  flow::EdgeField start_flux;
  std::vector<double> start_lumped, start_forcing;
  if (in) {
    in->read_state(start);
    start_step = in->info().step;
  }
  if (!immersed_setup.empty())  // only with [structure.<name>] tables
    p.immersed.emplace(std::move(immersed_setup), p.local, p.run_path, p.in_place, start_step);
  if (in) {
    if (p.immersed) p.immersed->restore(*in);
    if (in->has("pressure_increment"))  // the Poisson warm start (bitwise restarts)
      start_dp = io::read_nodal_array(*in, p.local, "pressure_increment");
    if (in->has("face_flux"))  // the projected face flux of the state (bitwise restarts)
      start_flux = io::read_edge_array(*in, p.local, "face_flux");
    if (p.les.subgrid_viscosity && in->has("subgrid_viscosity"))  // the first dt of an LES
      start_nu_sgs = io::read_nodal_array(*in, p.local, "subgrid_viscosity");
    if (in->has("lumped_outlets"))  // resistance/RCR states (flux, pressure, p_d, increment)
      start_lumped = io::read_replicated_array(*in, "lumped_outlets");
    if (in->has("flow_rate_control"))  // the force that holds the flow rate
      start_forcing = io::read_replicated_array(*in, "flow_rate_control");
    if (p.analysis) p.analysis->restore(*in);
    if (p.rank == 0 && p.print)
      fmt::print("restart: {} (step {}, t = {:.9g} s)\n", p.checkpoint->string(), start_step,
                 start.time);
    if (p.in_place && p.rank == 0)
      if (const auto rule = run::restart_step_rule_change(
              p.run_path / run::RunDirectory::resolved_scene_name, scene);
          !rule.empty())
        fmt::print(
            "restart: the time-step rule changes ({}): from here the run is not the "
            "bitwise continuation of the one before\n",
            rule);
  }
  if (valve_options) {  // [valve]
    const auto& ib = p.immersed->structure();
    int body = 0;
    while (ib.body(body).spec().name != valve_options->structure) ++body;
    p.valve_monitor.emplace(p.local, ib, body, *valve_options, p.run_path, p.in_place);
    if (in) p.valve_monitor->restore(*in);
  }
  if (p.in_place) p.fields_name = fmt::format("fields_restart_{:09d}", start_step);
  p.print_summary(scene, rho, run_options.projection.viscosity);
  if (p.immersed) run_options.coupling = p.immersed->coupling();
  run_options.boundary = std::move(boundary);
  phase.next(fmt::format("setting up the flow solver and the hypre Poisson matrix ({} local nodes)",
                         p.local.num_local()));
  auto sink = [&p](const std::string& stream, double time, const io::FieldSet& set) {
    p.write_fields(stream, time, set);
  };
  if (run_options.forcing.type == flow::ForcingSpec::Type::flow_rate) {
    // The controller's own cut of the forcing's section (read_forcing checked that it exists).
    const auto& sections = analysis_options.sections.sections;
    const auto it = std::find_if(sections.begin(), sections.end(), [&](const auto& s) {
      return s.name == run_options.forcing.section;
    });
    auto cut = std::make_shared<analysis::SectionFlux>(p.local, *it);
    run_options.section_flux = [cut](const flow::EdgeField& flux) { return cut->flux(flux); };
  }
  try {
    p.loop.emplace(p.mesh, p.metrics, p.local, run_options, sink);
  } catch (const run::RunError& e) {
    if (e.key().empty()) throw;
    throw std::runtime_error(scene.location(e.key()).str() + ": " + e.what());
  }
  if (p.analysis && p.loop->prescribed_force())
    p.analysis->set_body_force(p.loop->prescribed_force());
  if (p.analysis) p.analysis->set_viscosity_model(run_options.projection.rheology);
  if (p.analysis && p.immersed)
    p.analysis->set_support_nodes(
        [&p](std::vector<char>& nodes) { p.immersed->support_nodes(nodes); });
  if (p.checkpoint) {
    p.loop->resume(std::move(start), start_step, start_dp, start_nu_sgs, start_flux, start_lumped);
    p.loop->restore_forcing_state(start_forcing);
    p.les.resume(p.loop->subgrid_viscosity());
  }
  if (p.mesh_hash != 0 && checkpoints)
    p.writer.emplace(p.local, p.mesh_hash, p.run_path / "checkpoints", "checkpoint",
                     scene.get<int>("output.checkpoint_keep"));
  if (scene.get<bool>("output.checkpoint_on_signal")) p.stop.emplace();
}

Simulation::~Simulation() = default;

void Simulation::set_initial_velocity(
    const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
  auto& p = *parts_;
  if (p.checkpoint)
    throw std::logic_error("Simulation::set_initial_velocity on a restart from a checkpoint");
  flow::VectorField velocity(p.local.num_local());
  for (int i = 0; i < p.local.num_local(); ++i) velocity[i] = u(p.local.position[i]);
  p.loop->set_initial_velocity(std::move(velocity));
}

void Simulation::observe(StepObserver observer) {
  parts_->observer = std::move(observer);
}

void Simulation::modify_velocity(VelocityModifier modifier) {
  parts_->modifier = std::move(modifier);
}

RunResult Simulation::run() {
  auto& p = *parts_;
  Phase phase("time stepping (fields, analysis and checkpoints written on the way)");
  run::RunHooks hooks;
  hooks.after_step = [this, &p](const flow::FlowState& state, std::int64_t step) {
    if (p.analysis) p.analysis->sample(state, step, p.loop->face_flux());
    if (p.immersed) p.immersed->after_step(state.time, step);
    if (p.valve_monitor) p.valve_monitor->sample(state, step);
    if (p.observer) p.observer(*this, step);
  };
  if (p.modifier)
    hooks.modify_velocity = [this, &p](flow::FlowState& state, std::int64_t step) {
      p.modifier(*this, state.velocity, step);
    };
  if (p.writer)
    hooks.checkpoint = [&p](const flow::FlowState& state, std::int64_t step, double dt,
                            run::RunHooks::Moment moment) {
      p.write_checkpoint(state, step, dt, moment);
    };
  hooks.stop_requested = [&p] {
    // Collective (StopSignal::requested reduces over the ranks); the observer's request is
    // made on every rank alike.
    const bool signalled = p.stop && p.stop->requested(p.comm);
    if (signalled) p.stopped_by_signal = true;
    return signalled || p.stop_requested;
  };
  p.loop->set_hooks(std::move(hooks));
  if (!p.checkpoint) {  // the initial state (a new run)
    if (p.analysis) p.analysis->sample(p.loop->state(), 0, p.loop->face_flux());
    if (p.valve_monitor) p.valve_monitor->sample(p.loop->state(), 0);
  }
  p.last_write = Clock::now();
  RunResult result;
  result.run_path = p.run_path;
  try {
    result.summary = p.loop->run();
    result.stopped_by_signal = p.stopped_by_signal;
  } catch (const run::RunError& e) {
    if (e.key().empty()) throw;
    throw std::runtime_error(p.scene.location(e.key()).str() + ": " + e.what());
  }
  phase.next("writing the analysis results");
  if (p.analysis) p.analysis->finish();
  result.last_checkpoint = p.last_checkpoint;
  if (p.outputs.count(p.fields_name)) result.fields_xmf = p.outputs.at(p.fields_name)->xmf_file();
  return result;
}

void Simulation::request_stop() const {
  parts_->stop_requested = true;
}

const mesh::Mesh& Simulation::mesh() const {
  return parts_->mesh;
}
const mesh::DualMetrics& Simulation::metrics() const {
  return parts_->metrics;
}
const run::RunLoop& Simulation::loop() const {
  return *parts_->loop;
}
const ibm::ImmersedStructure* Simulation::immersed() const {
  return parts_->immersed ? &parts_->immersed->structure() : nullptr;
}
const mesh::LocalMesh& Simulation::local() const {
  return parts_->local;
}
const flow::FlowState& Simulation::state() const {
  return parts_->loop->state();
}
const analysis::RunAnalysis* Simulation::analysis() const {
  return parts_->analysis ? &*parts_->analysis : nullptr;
}
double Simulation::subgrid_cpu_seconds() const {
  return parts_->les.cpu_seconds();
}
const std::filesystem::path& Simulation::run_path() const {
  return parts_->run_path;
}

}  // namespace valsalva::run
