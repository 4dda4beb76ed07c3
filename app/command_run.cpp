// `valsalva run`: a scene (with --set overrides) through run::Simulation, and the lines that
// tell the user where the results are.
#include <fmt/format.h>
#include <mpi.h>

#include <chrono>

#include "app/commands.hpp"
#include "run/phase.hpp"
#include "run/simulation.hpp"
#include "run/stop_signal.hpp"
#include "scene/scene.hpp"

namespace valsalva::app {

int run_scene(const std::filesystem::path& scene_file, const std::vector<std::string>& settings,
              const run::RunRequest& request) {
  const auto t0 = std::chrono::steady_clock::now();
  run::Phase phase("reading the scene " + scene_file.string());
  const auto scene = scene::load_scene(scene_file, settings);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0 && !request.quiet)
    fmt::print("# resolved scene {}\n{}\n", scene_file.string(), scene.resolved());
  run::Simulation simulation(scene, request);
  if (rank == 0 && !request.quiet)
    fmt::print(
        "set-up: {:.2f} s (scene, mesh, dual metrics, partition, structures and analysis; the "
        "Poisson hierarchy is built in the first step)\n",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const auto result = simulation.run();
  const auto& summary = result.summary;
  if (rank != 0) return 0;
  if (summary.stopped) {
    fmt::print(
        "stopped by signal {} at step {} (t = {:.9g} s); checkpoint {}\ncontinue with: "
        "valsalva run {} --out {} --restart latest\n",
        run::StopSignal::signal_number(), summary.steps, summary.time,
        result.last_checkpoint.string(), scene_file.string(), result.run_path.string());
    return 0;
  }
  const auto& at = summary.max_divergence_position;
  fmt::print(
      "finished: {} steps to t = {:.6g} s, max |div v| {:.3e} 1/s (|div v| h / max|v| {:.3e} at "
      "({:.4g}, {:.4g}, {:.4g}) m, t = {:.6g} s), max Poisson iterations {}\n",
      summary.steps, summary.time, summary.max_divergence, summary.max_divergence_number, at.x(),
      at.y(), at.z(), summary.max_divergence_time, summary.max_poisson_iterations);
  const auto& free_at = summary.max_free_divergence_position;
  fmt::print(
      "without wall and inflow nodes: |div v| h / max|v| {:.3e} at ({:.4g}, {:.4g}, {:.4g}) m, "
      "t = {:.6g} s\n",
      summary.max_free_divergence_number, free_at.x(), free_at.y(), free_at.z(),
      summary.max_free_divergence_time);
  if (summary.steady)
    fmt::print("steady state: max |u^(n+1) - u^n| / dt {:.3e} m/s2 below time.steady_tolerance\n",
               summary.change_rate);
  if (!result.fields_xmf.empty())
    fmt::print("results: {} (open {} in ParaView)\n", result.run_path.string(),
               result.fields_xmf.string());
  else
    fmt::print("results: {} (no fields: output.interval = 0)\n", result.run_path.string());
  fmt::print("wall time: {:.2f} s\n",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}

}  // namespace valsalva::app
