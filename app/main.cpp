// valsalva command-line front end: parses arguments and hands over to the library.
#include <fmt/format.h>
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>

#include "app/command_close_leaflets.hpp"
#include "app/command_compare_piv.hpp"
#include "app/command_export_piv.hpp"
#include "app/command_make_valve.hpp"
#include "app/command_plot_valve.hpp"
#include "app/command_psd.hpp"
#include "app/commands.hpp"
#include "core/allocation_limit.hpp"
#include "run/phase.hpp"

int main(int argc, char** argv) {
  // Line-buffered stdout, so that a run or validation case redirected to a file (or piped to
  // tee) can be followed while it runs (the status line flushes itself after each '\r').
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);

  CLI::App cli{
      "valsalva: blood flow through heart valves (incompressible LES + immersed leaflets)"};
  cli.require_subcommand(1);
  std::string scene, mesh_file, case_name, out, restart;
  bool overwrite = false, list = false, quick = false, quiet = false;
  double scale = 1.0;

  auto* run = cli.add_subcommand("run", "Run a scene; results go to its run directory");
  run->add_option("scene", scene, "Scene file (TOML)")->required();
  run->add_flag("--overwrite", overwrite, "Replace the results of an earlier run of this scene");
  run->add_option("--out", out, "Run directory (default: run.output_dir, else runs/<scene>)");
  run->add_option("--restart", restart,
                  "Continue from a checkpoint FILE, or 'latest' in <run dir>/checkpoints");
  run->add_flag("--quiet", quiet, "Print only the start and the end of the run (run.progress)");
  std::vector<std::string> scene_settings;
  run->add_option("--set", scene_settings,
                  "Scene override KEY=VALUE, VALUE in TOML (repeatable; a bare word is a string)")
      ->allow_extra_args(false);

  auto* check = cli.add_subcommand("check", "Validate a scene and its mesh without running");
  check->add_option("scene", scene, "Scene file (TOML)")->required();
  check->add_option("--set", scene_settings, "Scene override KEY=VALUE (as for run)")
      ->allow_extra_args(false);

  auto* info = cli.add_subcommand("mesh-info", "Counts, patches, volumes and quality of a mesh");
  info->add_option("mesh", mesh_file, "Gmsh .msh file")->required();
  info->add_option("--scale", scale, "Factor applied to coordinates (e.g. 0.001 for mm)");

  auto* val = cli.add_subcommand("validate", "Run a verification/validation case");
  val->add_option("case", case_name, "Case name (see --list)");
  val->add_flag("--list", list, "List the cases");
  val->add_flag("--quick", quick, "Short version of the case");
  val->add_option("--out", out, "Output folder (default: validation-results/<case>)");
  std::vector<std::string> case_settings;
  bool case_options = false;
  val->add_option("--set", case_settings,
                  "Case option KEY=VALUE (repeatable; --options lists the case's options)")
      ->allow_extra_args(false);
  val->add_flag("--options", case_options, "List the case's options and exit");
  bool record = false;
  val->add_flag("--record", record,
                "Store the run's report as the case's record of this level "
                "(validation/<case>/results/{quick,full}.json, read by docs-validation)");

  auto* docs = cli.add_subcommand("docs-scenes", "Print the scene-key reference (docs/scenes.md)");
  auto* docs_val = cli.add_subcommand(
      "docs-validation", "Print the validation status (docs/validation.md) from the case records");

  std::function<int()> compare_piv;
  auto* piv = valsalva::app::add_compare_piv(cli, compare_piv);
  std::function<int()> export_piv;
  auto* export_piv_cmd = valsalva::app::add_export_piv(cli, export_piv);
  std::function<int()> psd;
  auto* psd_cmd = valsalva::app::add_psd(cli, psd);
  std::function<int()> plot_valve;
  auto* plot_valve_cmd = valsalva::app::add_plot_valve(cli, plot_valve);
  std::function<int()> close_leaflets;
  auto* close_cmd = valsalva::app::add_close_leaflets(cli, close_leaflets);
  std::function<int()> make_valve;
  auto* make_valve_cmd = valsalva::app::add_make_valve(cli, make_valve);

  int code = 0;
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    code = rank == 0 ? cli.exit(e) : (e.get_exit_code() == 0 ? 0 : 2);
    MPI_Finalize();
    return code;
  }
  try {
    if (*run)
      code = valsalva::app::run_scene(scene, scene_settings, {out, overwrite, restart, quiet});
    if (*check) code = valsalva::app::check_scene(scene, scene_settings);
    if (*info) code = valsalva::app::mesh_info(mesh_file, scale);
    if (*val)
      code =
          valsalva::app::validate(case_name, list, quick, out, case_settings, case_options, record);
    if (*docs) code = valsalva::app::docs_scenes();
    if (*docs_val) code = valsalva::app::docs_validation();
    if (*piv) code = compare_piv();
    if (*export_piv_cmd) code = export_piv();
    if (*psd_cmd) code = psd();
    if (*plot_valve_cmd) code = plot_valve();
    if (*close_cmd) code = close_leaflets();
    if (*make_valve_cmd) code = make_valve();
  } catch (const std::bad_alloc&) {
    // Says nothing by itself: name the step that ran out of memory (app/phase.hpp).
    const auto& phase = valsalva::run::Phase::current();
    if (size == 1 || rank == 0)
      fmt::print(stderr,
                 "valsalva: error: out of memory while {} (std::bad_alloc: the input asks for "
                 "more memory than this process may use; {} of physical memory, {} rank(s))\n",
                 phase.empty() ? "running the command" : phase,
                 valsalva::core::byte_size(valsalva::core::physical_memory_bytes()), size);
    if (size > 1) MPI_Abort(MPI_COMM_WORLD, 1);
    code = 1;
  } catch (const std::exception& e) {
    // Inputs are read on every rank, so every rank fails alike; with several ranks a failure on
    // one rank alone must not leave the others waiting in a collective.
    if (size == 1 || rank == 0) fmt::print(stderr, "valsalva: error: {}\n", e.what());
    if (size > 1) MPI_Abort(MPI_COMM_WORLD, 1);
    code = 1;
  }
  MPI_Finalize();
  return code;
}
