// `valsalva run`: a scene from its mesh to its results — run directory, restart, fields,
// checkpoints, the analysis the scene asks for (io/run_analysis.hpp) and the progress display.
#include <fmt/format.h>
#include <mpi.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>

#include "app/commands.hpp"
#include "app/phase.hpp"
#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
#include "io/immersed_run.hpp"
#include "io/mesh_source.hpp"
#include "io/restart_continuity.hpp"
#include "io/run_analysis.hpp"
#include "io/run_directory.hpp"
#include "io/scene.hpp"
#include "io/scene_keys_analysis.hpp"
#include "io/scene_keys_boundary.hpp"
#include "io/scene_keys_flow.hpp"
#include "io/scene_keys_les.hpp"
#include "io/scene_keys_structure.hpp"
#include "io/scene_keys_valve.hpp"
#include "io/stop_signal.hpp"
#include "valve/valve_monitor.hpp"

namespace valsalva::app {

namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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
double cycle_period(const io::AnalysisOptions& analysis,
                    const std::vector<flow::BoundarySpec>& boundary) {
  for (const auto& s : analysis.statistics)
    if (s.phase.period > 0) return s.phase.period;
  for (const auto& b : boundary)
    if (b.type == flow::BoundaryType::inlet && b.flow_rate.kind != flow::Waveform::Kind::constant)
      return b.flow_rate.period;
  return 0;
}

flow::Progress progress_mode(const io::Scene& scene, bool quiet) {
  const auto mode = scene.get<std::string>("run.progress");
  if (quiet || mode == "quiet") return flow::Progress::quiet;
  if (mode == "lines") return flow::Progress::lines;
  if (mode == "status") return flow::Progress::status;
  // Open MPI hands its processes a pseudo-terminal even when mpiexec's own output goes to a
  // file, so under mpiexec (OMPI_COMM_WORLD_SIZE, PMI_SIZE) "auto" keeps plain lines.
  const bool mpiexec = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE");
  return isatty(fileno(stdout)) && !mpiexec ? flow::Progress::status : flow::Progress::lines;
}

}  // namespace

int run_scene(const fs::path& scene_file, bool overwrite, const std::string& out,
              const std::string& restart, bool quiet) {
  const auto t0 = std::chrono::steady_clock::now();
  Phase phase("reading the scene " + scene_file.string());
  const auto scene = io::load_scene(scene_file);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0 && !quiet)
    fmt::print("# resolved scene {}\n{}\n", scene_file.string(), scene.resolved());
  const auto dir = out.empty() ? io::default_run_path(scene) : fs::path(out);
  const bool wipe = overwrite || scene.get<bool>("run.overwrite");
  // A restart continues in the run directory of the checkpoint when it is that directory (or
  // "latest"): nothing there is deleted, the logs are appended to and the fields go to a new
  // fields_restart_<step>.xmf. Otherwise (a checkpoint from elsewhere) the run directory is
  // prepared as for a new run, with the same --overwrite promise.
  const auto checkpoint = restart_checkpoint(restart, dir);
  const bool in_place =
      checkpoint && fs::exists(dir / io::RunDirectory::resolved_scene_name) &&
      fs::equivalent(fs::absolute(*checkpoint).parent_path(), fs::absolute(dir / "checkpoints"));
  if (in_place && wipe)
    throw std::runtime_error(fmt::format(
        "--restart {} with --overwrite (or run.overwrite) would delete the checkpoint with the "
        "run directory {}: drop --overwrite to continue there, or give another --out",
        checkpoint->string(), dir.string()));
  if (in_place)
    if (const auto change =
            io::restart_scene_change(dir / io::RunDirectory::resolved_scene_name, scene);
        !change.empty())
      throw std::runtime_error(change);

  // Everything the scene can get wrong is checked before the run directory is touched.
  phase.next(mesh_phase(scene));
  const auto mesh = io::build_mesh(scene);
  phase.next(fmt::format("computing the dual metrics of the mesh ({} nodes, {} cells)",
                         mesh.num_nodes(), mesh.num_cells()));
  const auto metrics = flow::compute_dual_metrics(mesh);
  phase.next("checking the scene against the mesh");
  auto boundary = io::read_boundary_conditions(scene, mesh);
  const auto analysis_options = io::read_analysis_options(scene, mesh);
  auto immersed_setup = io::read_immersed_setup(scene, mesh);
  const auto valve_options = io::read_valve_monitor_options(scene, mesh);
  io::check_les_scene(scene);
  io::flow_run_options(scene, dir);  // its checks (time step, output volume), before any write
  io::check_initial_state(scene, mesh);
  io::check_step_count(scene, metrics);
  const fs::path run_path =
      in_place ? dir : io::RunDirectory::prepare(dir, wipe, scene, MPI_COMM_WORLD).path();

  flow::PartitionOptions options;
  options.ghost_layers = scene.get<int>("partition.ghost_layers");
  options.method = scene.get<std::string>("partition.method");
  phase.next(fmt::format("partitioning the mesh ({} dual nodes, partition.method = {})",
                         metrics.num_nodes(), options.method));
  auto local = flow::distribute(mesh, metrics, MPI_COMM_WORLD, options);
  phase.next(
      fmt::format("setting up the LES model, the analysis and the structures ({} local "
                  "nodes)",
                  local.num_local()));

  auto run_options = io::flow_run_options(scene, run_path);
  const auto les = io::les_setup(scene, local);  // nu_sgs/nu joins the fields with a model
  run_options.projection.subgrid_viscosity = les.subgrid_viscosity;
  run_options.output.progress = progress_mode(scene, quiet);
  run_options.output.cycle_period = cycle_period(analysis_options, boundary);
  const double rho = run_options.projection.density;
  std::uint64_t hash = 0;
  const auto every_steps =
      static_cast<std::int64_t>(scene.get<int>("output.checkpoint_every_steps"));
  const double every_seconds = 60 * scene.get<double>("output.checkpoint_every_minutes");
  const bool on_signal = scene.get<bool>("output.checkpoint_on_signal");
  if (checkpoint || every_steps > 0 || every_seconds > 0 || on_signal) hash = io::mesh_hash(mesh);
  std::optional<io::CheckpointReader> in;
  if (checkpoint) {
    in.emplace(local, hash, *checkpoint);  // throws on another mesh
    const double end = scene.get<double>("time.end");
    if (end < in->info().time * (1 - 1e-12))
      throw scene.error("time.end",
                        fmt::format("{:.9g} s is before the time of checkpoint '{}', {:.9g} s: "
                                    "nothing to continue",
                                    end, checkpoint->string(), in->info().time),
                        fmt::format(">= {:.9g}", in->info().time));
    if (in_place) {
      std::vector<std::string> series{"log.csv"};
      if (!analysis_options.probes.points.empty()) series.push_back("probes.csv");
      if (!analysis_options.pressure_drops.empty()) series.push_back("pressure_drop.csv");
      if (!analysis_options.sections.sections.empty()) series.push_back("sections.csv");
      if (!analysis_options.wall_shear.patches.empty()) series.push_back("wall_shear_history.csv");
      if (!immersed_setup.empty()) series.push_back("structures.csv");
      if (valve_options) series.push_back("valve.csv");
      io::continue_in_place(run_path, scene, in->info().step, in->info().time, in->info().dt,
                            series, local.comm);
    }
  }
  std::optional<io::RunAnalysis> analysis;
  if (!analysis_options.empty())
    analysis.emplace(mesh, metrics, local, analysis_options, rho,
                     rho * run_options.projection.viscosity, run_path, in_place);

  std::int64_t start_step = 0;
  flow::FlowState start;
  flow::ScalarField start_dp, start_nu_sgs;
  flow::EdgeField start_flux;
  std::optional<io::ImmersedRun> immersed;  // only with [structure.<name>] tables
  auto make_immersed = [&](std::int64_t step) {
    if (!immersed_setup.empty())
      immersed.emplace(std::move(immersed_setup), local, run_path, in_place, step);
  };
  if (!checkpoint) make_immersed(0);
  if (in) {
    in->read_state(start);
    start_step = in->info().step;
    make_immersed(start_step);
    if (immersed) immersed->restore(*in);
    if (in->has("pressure_increment"))  // the Poisson warm start (bitwise restarts)
      start_dp = io::read_nodal_array(*in, local, "pressure_increment");
    if (in->has("face_flux"))  // the projected face flux of the state (bitwise restarts)
      start_flux = io::read_edge_array(*in, local, "face_flux");
    if (les.subgrid_viscosity && in->has("subgrid_viscosity"))  // the first dt of an LES
      start_nu_sgs = io::read_nodal_array(*in, local, "subgrid_viscosity");
    if (analysis) analysis->restore(*in);
    if (rank == 0)
      fmt::print("restart: {} (step {}, t = {:.9g} s)\n", checkpoint->string(), start_step,
                 start.time);
  }
  std::optional<valve::ValveMonitor> valve_monitor;  // [valve]
  if (valve_options) {
    const auto& ib = immersed->structure();
    int body = 0;
    while (ib.body(body).spec().name != valve_options->structure) ++body;
    valve_monitor.emplace(local, ib, body, *valve_options, run_path, in_place);
    if (in) valve_monitor->restore(*in);
  }

  // Fields go to <basename>.xmf/.h5 in the run directory: "fields" at the output interval,
  // "last_good" when the run stops on a bad state. FieldOutput is collective; the run loop
  // calls the sink on every rank. Continuing in place must not replace the earlier fields:
  // they get a name of their own.
  std::map<std::string, std::unique_ptr<io::FieldOutput>> outputs;
  const std::string fields_name =
      in_place ? fmt::format("fields_restart_{:09d}", start_step) : std::string("fields");
  auto sink = [&](const std::string& stream, double time, const flow::FieldSet& set) {
    const std::string basename = stream == "fields" ? fields_name : stream;
    auto& o = outputs[basename];
    if (!o) o = std::make_unique<io::FieldOutput>(mesh, metrics, local, run_path, basename);
    std::vector<io::FieldOutput::Scalar> scalars;
    std::vector<io::FieldOutput::Vector> vectors;
    flow::FieldSet all = set;
    static const std::vector<io::PhaseStatistics> no_statistics;
    les.add_fields(all, time, *set.state_velocity,
                   analysis ? analysis->statistics() : no_statistics);
    if (immersed && stream == "fields") immersed->write(time, all);  // + the Lagrangian meshes
    for (const auto& [name, f] : all.scalars) scalars.push_back({name, f});
    for (const auto& [name, f] : all.vectors) vectors.push_back({name, f});
    o->write(time, scalars, vectors);
  };
  if (rank == 0) {
    fmt::print(
        "mesh: {} nodes ({} dual nodes), {} cells; partition: {} ranks, {} ghost layers, "
        "method {}\n",
        mesh.num_nodes(), metrics.num_nodes(), mesh.num_cells(), local.comm.size(),
        options.ghost_layers, options.method);
    fmt::print("flow: rho {:.6g} kg/m3, nu {:.6g} m2/s, scheme {}, initial state {}\n", rho,
               run_options.projection.viscosity, scene.get<std::string>("flow.scheme"),
               run_options.initial.type);
  }
  if (rank == 0 && les.subgrid_viscosity)
    fmt::print("les: model {}, constant {:.4g}\n", les.model, les.constant);
  if (immersed) {
    const auto& ib = immersed->structure();
    const auto& o = ib.options();
    if (rank == 0)
      fmt::print(
          "immersed: {} structure(s), {} markers, kernel {} width {} h, coupling {}, dt bound "
          "{:.4e} s (dt_safety {})\n",
          ib.num_bodies(), ib.num_markers(), ibm::kernel_name(o.transfer.kernel.type),
          o.transfer.kernel.width,
          o.mode == ibm::CouplingMode::per_stage ? "per_stage" : "per_step", immersed->dt_bound(),
          o.stability_safety);
    run_options.coupling = immersed->coupling();
  }
  run_options.boundary = std::move(boundary);
  phase.next(fmt::format("setting up the flow solver and the hypre Poisson matrix ({} local nodes)",
                         local.num_local()));
  flow::RunLoop loop(mesh, metrics, local, run_options, sink);
  if (checkpoint) {
    loop.resume(std::move(start), start_step, start_dp, start_nu_sgs, start_flux);
    les.resume(loop.subgrid_viscosity());
  }
  if (analysis && !checkpoint) analysis->sample(loop.state(), 0, loop.face_flux());
  if (valve_monitor && !checkpoint) valve_monitor->sample(loop.state(), 0);

  // Checkpoints every N steps, every M wall-clock minutes (rank 0's clock decides, so that all
  // ranks agree) and on SIGINT/SIGTERM; the newest output.checkpoint_keep are kept. They carry
  // the Poisson warm start and the analysis accumulators.
  std::optional<io::CheckpointWriter> writer;
  std::optional<io::StopSignal> stop;
  fs::path last_checkpoint;
  if (hash != 0 && (every_steps > 0 || every_seconds > 0 || on_signal))
    writer.emplace(local, hash, run_path / "checkpoints", "checkpoint",
                   scene.get<int>("output.checkpoint_keep"));
  if (on_signal) stop.emplace();
  auto last_write = std::chrono::steady_clock::now();
  flow::RunHooks hooks;
  if (analysis)
    hooks.after_step = [&](const flow::FlowState& state, std::int64_t step) {
      analysis->sample(state, step, loop.face_flux());
    };
  if (immersed) {
    auto previous = std::move(hooks.after_step);
    hooks.after_step = [&, previous](const flow::FlowState& state, std::int64_t step) {
      if (previous) previous(state, step);
      immersed->after_step(state.time, step);
      if (valve_monitor) valve_monitor->sample(state, step);
    };
  }
  if (writer)
    hooks.checkpoint = [&](const flow::FlowState& state, std::int64_t step, double dt,
                           bool stopping) {
      bool due = stopping || (every_steps > 0 && step % every_steps == 0);
      if (every_seconds > 0) {
        int late = seconds_since(last_write) >= every_seconds ? 1 : 0;
        MPI_Bcast(&late, 1, MPI_INT, 0, MPI_COMM_WORLD);
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
          io::nodal_checkpoint_array("pressure_increment", local, loop.pressure_increment()));
      if (!loop.face_flux().empty())
        extras.push_back(io::edge_checkpoint_array("face_flux", local, loop.face_flux()));
      if (!loop.subgrid_viscosity().empty())
        extras.push_back(
            io::nodal_checkpoint_array("subgrid_viscosity", local, loop.subgrid_viscosity()));
      last_checkpoint = writer->write(state, step, dt, extras);
      last_write = std::chrono::steady_clock::now();
    };
  if (stop) hooks.stop_requested = [&] { return stop->requested(MPI_COMM_WORLD); };
  loop.set_hooks(std::move(hooks));
  flow::RunSummary summary;
  phase.next("time stepping (fields, analysis and checkpoints written on the way)");
  try {
    summary = loop.run();
  } catch (const flow::RunError& e) {
    if (e.key().empty()) throw;
    throw std::runtime_error(scene.location(e.key()).str() + ": " + e.what());
  }
  phase.next("writing the analysis results");
  if (analysis) analysis->finish();
  if (summary.stopped) {
    if (rank == 0)
      fmt::print(
          "stopped by signal {} at step {} (t = {:.9g} s); checkpoint {}\ncontinue with: "
          "valsalva run {} --out {} --restart latest\n",
          io::StopSignal::signal_number(), summary.steps, summary.time, last_checkpoint.string(),
          scene_file.string(), run_path.string());
    return 0;
  }
  if (rank == 0) {
    fmt::print(
        "finished: {} steps to t = {:.6g} s, max |div v| {:.3e} 1/s (|div v| h / max|v| "
        "{:.3e}), max Poisson iterations {}\n",
        summary.steps, summary.time, summary.max_divergence, summary.max_divergence_number,
        summary.max_poisson_iterations);
    if (outputs.count(fields_name))
      fmt::print("results: {} (open {} in ParaView)\n", run_path.string(),
                 outputs.at(fields_name)->xmf_file().string());
    else
      fmt::print("results: {} (no fields: output.interval = 0)\n", run_path.string());
    fmt::print("wall time: {:.2f} s\n", seconds_since(t0));
  }
  return 0;
}

}  // namespace valsalva::app
