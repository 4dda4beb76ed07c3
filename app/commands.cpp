#include "app/commands.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/mesh_check.hpp"
#include "flow/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "io/field_output.hpp"
#include "io/gmsh_reader.hpp"
#include "io/mesh_info.hpp"
#include "io/mesh_source.hpp"
#include "io/run_directory.hpp"
#include "io/scene.hpp"
#include "io/scene_docs.hpp"
#include "io/scene_keys_boundary.hpp"
#include "io/scene_keys_flow.hpp"
#include "io/scene_keys_les.hpp"
#include "io/stop_signal.hpp"
#include "validation/case.hpp"

namespace valsalva::app {

namespace {

int world_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int check_scene(const std::filesystem::path& scene_file) {
  const auto scene = io::load_scene(scene_file);
  const auto mesh = io::build_mesh(scene);
  const auto metrics = flow::compute_dual_metrics(mesh);
  io::read_boundary_conditions(scene, mesh);  // every non-periodic patch has a valid condition
  if (world_rank() == 0)
    fmt::print("{}: scene and mesh are valid ({} nodes, {} cells, {} boundary patches)\n",
               scene_file.string(), metrics.num_nodes(), mesh.num_cells(), mesh.patch_names.size());
  return 0;
}

int run_scene(const std::filesystem::path& scene_file, bool overwrite, const std::string& out,
              const std::string& restart) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  const auto scene = io::load_scene(scene_file);
  const int rank = world_rank();
  if (rank == 0) fmt::print("# resolved scene {}\n{}\n", scene_file.string(), scene.resolved());
  const auto dir = out.empty() ? io::default_run_path(scene) : fs::path(out);
  const bool wipe = overwrite || scene.get<bool>("run.overwrite");
  // A restart continues in the run directory of the checkpoint when it is that directory (or
  // "latest"): nothing there is deleted, the log is appended to and the fields go to a new
  // fields_restart_<step>.xmf. Otherwise (a checkpoint from elsewhere) the run directory is
  // prepared as for a new run, with the same --overwrite promise.
  std::optional<fs::path> checkpoint;
  if (restart == "latest") {
    checkpoint = io::latest_checkpoint(dir / "checkpoints");
    if (!checkpoint)
      throw std::runtime_error(
          fmt::format("--restart latest: no checkpoint in {}", (dir / "checkpoints").string()));
  } else if (!restart.empty()) {
    checkpoint = fs::path(restart);
    if (!fs::is_regular_file(*checkpoint))
      throw std::runtime_error(fmt::format("--restart {}: no such file", restart));
  }
  const bool in_place =
      checkpoint && fs::exists(dir / io::RunDirectory::resolved_scene_name) &&
      fs::equivalent(fs::absolute(*checkpoint).parent_path(), fs::absolute(dir / "checkpoints"));
  if (in_place && wipe)
    throw std::runtime_error(fmt::format(
        "--restart {} with --overwrite (or run.overwrite) would delete the checkpoint with the "
        "run directory {}: drop --overwrite to continue there, or give another --out",
        checkpoint->string(), dir.string()));
  const fs::path run_path =
      in_place ? dir : io::RunDirectory::prepare(dir, wipe, scene, MPI_COMM_WORLD).path();

  const auto mesh = io::build_mesh(scene);
  const auto metrics = flow::compute_dual_metrics(mesh);
  flow::PartitionOptions options;
  options.ghost_layers = scene.get<int>("partition.ghost_layers");
  options.method = scene.get<std::string>("partition.method");
  const auto local = flow::distribute(mesh, metrics, MPI_COMM_WORLD, options);

  // Fields go to <basename>.xmf/.h5 in the run directory: "fields" at the output interval,
  // "last_good" when the run stops on a bad state. FieldOutput is collective; the run loop
  // calls the sink on every rank.
  const auto les = io::les_setup(scene, local);  // nu_sgs/nu joins the fields with a model
  std::map<std::string, std::unique_ptr<io::FieldOutput>> outputs;
  std::int64_t start_step = 0;
  flow::FlowState start;
  flow::ScalarField start_dp;
  std::uint64_t hash = 0;
  if (checkpoint || scene.get<int>("output.checkpoint_every_steps") > 0 ||
      scene.get<double>("output.checkpoint_every_minutes") > 0 ||
      scene.get<bool>("output.checkpoint_on_signal"))
    hash = io::mesh_hash(mesh);
  if (checkpoint) {
    io::CheckpointReader in(local, hash, *checkpoint);  // throws on another mesh
    in.read_state(start);
    start_step = in.info().step;
    if (in.has("pressure_increment")) {  // the Poisson warm start (bitwise restarts)
      std::vector<std::int64_t> rows(local.dual_node.begin(), local.dual_node.end());
      start_dp = in.read_array("pressure_increment", rows);
    }
    if (rank == 0)
      fmt::print("restart: {} (step {}, t = {:.9g} s)\n", checkpoint->string(), start_step,
                 start.time);
  }
  // Continuing in place must not replace the earlier fields: they get a name of their own.
  const std::string fields_name =
      in_place ? fmt::format("fields_restart_{:09d}", start_step) : std::string("fields");
  if (in_place && fs::exists(run_path / (fields_name + ".xmf")) && !wipe)
    throw std::runtime_error(fmt::format(
        "{} exists: this checkpoint was already restarted from in {}; give another --out",
        (run_path / (fields_name + ".xmf")).string(), run_path.string()));
  auto sink = [&](const std::string& stream, double time, const flow::FieldSet& set) {
    const std::string basename = stream == "fields" ? fields_name : stream;
    auto& o = outputs[basename];
    if (!o) o = std::make_unique<io::FieldOutput>(mesh, metrics, local, run_path, basename);
    std::vector<io::FieldOutput::Scalar> scalars;
    std::vector<io::FieldOutput::Vector> vectors;
    flow::FieldSet all = set;
    les.add_fields(all);
    for (const auto& [name, f] : all.scalars) scalars.push_back({name, f});
    for (const auto& [name, f] : set.vectors) vectors.push_back({name, f});
    o->write(time, scalars, vectors);
  };
  auto run_options = io::flow_run_options(scene, run_path);
  run_options.projection.subgrid_viscosity = les.subgrid_viscosity;
  if (rank == 0) {
    fmt::print(
        "mesh: {} nodes ({} dual nodes), {} cells; partition: {} ranks, {} ghost layers, "
        "method {}\n",
        mesh.num_nodes(), metrics.num_nodes(), mesh.num_cells(), local.comm.size(),
        options.ghost_layers, options.method);
    fmt::print("flow: rho {:.6g} kg/m3, nu {:.6g} m2/s, scheme {}, initial state {}\n",
               run_options.projection.density, run_options.projection.viscosity,
               scene.get<std::string>("flow.scheme"), run_options.initial.type);
  }
  if (rank == 0 && les.subgrid_viscosity)
    fmt::print("les: model {}, constant {:.4g}\n", les.model, les.constant);
  auto flow_options = run_options;  // and the boundary conditions, checked against the mesh
  flow_options.boundary = io::read_boundary_conditions(scene, mesh);
  flow::RunLoop loop(mesh, metrics, local, flow_options, sink);
  if (checkpoint) loop.resume(std::move(start), start_step, start_dp);

  // Checkpoints every N steps, every M wall-clock minutes (rank 0's clock decides, so that all
  // ranks agree) and on SIGINT/SIGTERM; the newest output.checkpoint_keep are kept.
  const auto every_steps =
      static_cast<std::int64_t>(scene.get<int>("output.checkpoint_every_steps"));
  const double every_seconds = 60 * scene.get<double>("output.checkpoint_every_minutes");
  std::optional<io::CheckpointWriter> writer;
  std::optional<io::StopSignal> stop;
  fs::path last_checkpoint;
  if (hash != 0 &&
      (every_steps > 0 || every_seconds > 0 || scene.get<bool>("output.checkpoint_on_signal")))
    writer.emplace(local, hash, run_path / "checkpoints", "checkpoint",
                   scene.get<int>("output.checkpoint_keep"));
  if (scene.get<bool>("output.checkpoint_on_signal")) stop.emplace();
  auto last_write = std::chrono::steady_clock::now();
  flow::RunHooks hooks;
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
      io::CheckpointArray dp{"pressure_increment", local.global_nodes, 0, {}, {}};
      const auto& increment = loop.pressure_increment();
      for (int i = 0; i < local.num_owned; ++i) {
        dp.rows.push_back(local.dual_node[i]);
        dp.data.push_back(increment[i]);
      }
      last_checkpoint = writer->write(state, step, dt, std::span(&dp, 1));
      last_write = std::chrono::steady_clock::now();
    };
  if (stop) hooks.stop_requested = [&] { return stop->requested(MPI_COMM_WORLD); };
  loop.set_hooks(std::move(hooks));
  flow::RunSummary summary;
  try {
    summary = loop.run();
  } catch (const flow::RunError& e) {
    if (e.key().empty()) throw;
    throw std::runtime_error(scene.location(e.key()).str() + ": " + e.what());
  }
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
        "finished: {} steps to t = {:.6g} s, max |div v| {:.3e} 1/s, max Poisson "
        "iterations {}\n",
        summary.steps, summary.time, summary.max_divergence, summary.max_poisson_iterations);
    if (outputs.count(fields_name))
      fmt::print("results: {} (open {} in ParaView)\n", run_path.string(),
                 outputs.at(fields_name)->xmf_file().string());
    else
      fmt::print("results: {} (no fields: output.interval = 0)\n", run_path.string());
    fmt::print("wall time: {:.2f} s\n", seconds_since(t0));
  }
  return 0;
}

int mesh_info(const std::filesystem::path& mesh_file, double scale) {
  auto mesh = io::read_gmsh(mesh_file);
  for (auto& x : mesh.nodes) x *= scale;
  flow::check_mesh(mesh);
  if (world_rank() == 0) std::cout << io::mesh_info(mesh);
  return 0;
}

int validate(const std::string& case_name, bool list, bool quick, const std::string& out) {
  const int rank = world_rank();
  if (list || case_name.empty()) {
    if (rank == 0)
      for (const auto& c : validation::all_cases())
        fmt::print("{:<28} {}\n", c.name, c.description);
    return list ? 0 : 2;
  }
  const auto* c = validation::find_case(case_name);
  if (!c)
    throw std::runtime_error(fmt::format(
        "validate: unknown case '{}' (valsalva validate --list shows the cases)", case_name));
  validation::Context ctx;
  ctx.quick = quick;
  ctx.out_dir = out.empty() ? std::filesystem::path("validation-results") / case_name
                            : std::filesystem::path(out);
  ctx.case_dir = std::filesystem::path(VALSALVA_SOURCE_DIR) / "validation" / case_name;
  ctx.refdata_dir = std::filesystem::path(VALSALVA_SOURCE_DIR) / "validation" / "refdata";
  if (rank == 0) std::filesystem::create_directories(ctx.out_dir);
  MPI_Barrier(MPI_COMM_WORLD);
  const auto t0 = std::chrono::steady_clock::now();
  validation::Report report;
  c->run(ctx, report);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const double wall = seconds_since(t0);
  if (rank == 0) {
    report.write_json(ctx.out_dir / "report.json", c->name, size, wall);
    for (const auto& m : report.metrics())
      fmt::print("{:<4} {:<48} value {:<14.6g} reference {:<14.6g} tolerance {:.3g}\n",
                 m.pass() ? "ok" : "FAIL", m.name, m.value, m.reference, m.tolerance);
    fmt::print("{}: {} ({:.1f} s) -> {}\n", c->name, report.all_pass() ? "PASS" : "FAIL", wall,
               (ctx.out_dir / "report.json").string());
  }
  const bool plotted = validation::run_plot_script(ctx);
  return report.all_pass() && plotted ? 0 : 1;
}

int docs_scenes() {
  io::write_scene_docs(std::cout);
  return 0;
}

}  // namespace valsalva::app
