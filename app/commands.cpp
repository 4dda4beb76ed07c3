#include "app/commands.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include "mesh/dual_metrics.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/mesh_info.hpp"
#include "run/data_dir.hpp"
#include "run/immersed_coupling.hpp"
#include "run/phase.hpp"
#include "scene/mesh_source.hpp"
#include "scene/scene.hpp"
#include "scene/scene_cycle_period.hpp"
#include "scene/scene_docs.hpp"
#include "scene/scene_keys_analysis.hpp"
#include "scene/scene_keys_boundary.hpp"
#include "scene/scene_keys_flow.hpp"
#include "scene/scene_keys_les.hpp"
#include "scene/scene_keys_structure.hpp"
#include "scene/scene_keys_valve.hpp"
#include "validation/case.hpp"
#include "validation/docs.hpp"
#include "validation/record.hpp"

namespace valsalva::app {

namespace {

using run::mesh_phase;
using run::Phase;

int world_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int check_scene(const std::filesystem::path& scene_file, const std::vector<std::string>& settings) {
  Phase phase("reading the scene " + scene_file.string());
  const auto scene = scene::load_scene(scene_file, settings);
  phase.next(mesh_phase(scene));
  const auto mesh = scene::build_mesh(scene, MPI_COMM_WORLD);
  phase.next(fmt::format("computing the dual metrics of the mesh ({} nodes, {} cells)",
                         mesh.num_nodes(), mesh.num_cells()));
  const auto metrics = mesh::compute_dual_metrics(mesh);
  phase.next("checking the scene against the mesh");
  const auto boundary =
      scene::read_boundary_conditions(scene, mesh);  // every patch has a condition
  scene::read_analysis_options(scene, mesh);         // probes, samples, statistics, wall shear
  const auto immersed = scene::read_immersed_setup(scene, mesh);  // meshes, materials, clamps
  scene::read_valve_monitor_options(scene, mesh);  // [valve]: its structure and patches
  scene::check_les_scene(scene);                   // LES output fields
  scene::flow_run_options(scene, {});              // time step, output volume
  scene::check_initial_state(scene, mesh);         // a Taylor-Green start on a 2 pi L-periodic mesh
  scene::check_forcing(scene, boundary);           // a flow-rate drive on a domain closed by walls
  scene::check_cycle_periods(scene);        // valve and statistics cycles against the inlet table
  scene::check_step_count(scene, metrics);  // the viscous bound on dt against time.end
  std::string coupling;
  if (!immersed.empty()) {  // every marker in the fluid, as the run places them
    phase.next("placing the immersed markers in the fluid mesh");
    auto local = mesh::distribute(mesh, metrics, MPI_COMM_WORLD);
    const auto c = run::build_immersed_coupling(immersed, local);
    coupling = fmt::format("; {} immersed markers, coupling time-step bound {:.3e} s",
                           c.structure->num_markers(), c.dt_bound);
  }
  if (world_rank() == 0)
    fmt::print("{}: scene and mesh are valid ({} nodes, {} cells, {} boundary patches{})\n",
               scene_file.string(), metrics.num_nodes(), mesh.num_cells(), mesh.patch_names.size(),
               coupling);
  return 0;
}

int mesh_info(const std::filesystem::path& mesh_file, double scale) {
  if (!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument(fmt::format(
        "mesh-info: --scale {} must be a positive finite factor (e.g. 0.001 for mm)", scale));
  Phase phase("reading the mesh " + mesh_file.string());
  auto mesh = mesh::read_gmsh(mesh_file);
  phase.next(
      fmt::format("checking the mesh ({} nodes, {} cells)", mesh.num_nodes(), mesh.num_cells()));
  for (auto& x : mesh.nodes) x *= scale;
  mesh::check_mesh(mesh);
  if (const auto pieces = scene::disconnected_pieces(mesh); !pieces.empty())
    throw std::runtime_error(pieces);
  if (world_rank() == 0) std::cout << mesh::mesh_info(mesh);
  return 0;
}

int validate(const std::string& case_name, bool list, bool quick, const std::string& out,
             const std::vector<std::string>& settings, bool show_options, bool record) {
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
  if (show_options) {
    if (rank == 0) {
      if (c->options.empty()) fmt::print("{} has no options\n", c->name);
      for (const auto& o : c->options)
        fmt::print("--set {}=VALUE  {}: {}\n", o.key, o.accepted(), o.help);
    }
    return 0;
  }
  if (record && !settings.empty())
    throw std::invalid_argument(
        "validate: --record stores the case's own levels; it cannot be combined with --set");
  validation::Context ctx;
  ctx.options = validation::parse_case_options(*c, settings);
  ctx.quick = quick;
  ctx.out_dir = out.empty() ? std::filesystem::path("validation-results") / case_name
                            : std::filesystem::path(out);
  ctx.case_dir = run::data_dir() / "validation" / case_name;
  ctx.refdata_dir = run::data_dir() / "validation" / "refdata";
  if (rank == 0) {
    std::filesystem::create_directories(ctx.out_dir);
    fmt::print("{}: case files and reference data from {}\n", c->name, ctx.case_dir.string());
  }
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
    if (record) {
      const auto level = quick ? validation::Level::quick : validation::Level::full;
      const auto command = fmt::format("{}valsalva validate {}{}",
                                       size > 1 ? fmt::format("mpiexec -n {} ", size) : "", c->name,
                                       quick ? " --quick" : "");
      const auto file = validation::record_file(ctx.case_dir, level);
      validation::write_record(
          file, validation::measured_record(c->name, level, report.to_json(c->name, size, wall),
                                            validation::current_origin(run::data_dir(), command)));
      fmt::print("{}: record -> {} (build/bin/valsalva docs-validation > docs/validation.md)\n",
                 c->name, file.string());
    }
  }
  const bool plotted = validation::run_plot_script(ctx);
  return report.all_pass() && plotted ? 0 : 1;
}

int docs_scenes() {
  scene::write_scene_docs(std::cout);
  return 0;
}

int docs_validation() {
  if (world_rank() == 0)
    validation::write_validation_docs(std::cout, run::data_dir() / "validation",
                                      validation::registered_case_docs());
  return 0;
}

}  // namespace valsalva::app
