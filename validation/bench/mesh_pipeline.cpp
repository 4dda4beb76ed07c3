// Benchmark of the mesh pipeline on a Gmsh tetrahedral pipe of about 1 M cells (opt-in, not a
// test): time to read the .msh file, compute the median-dual metrics and partition with METIS,
// and peak memory per node. Run: bench_mesh_pipeline [--target-size 0.00065] [--mesh FILE]
//   mpiexec -n 2 build/bin/bench_mesh_pipeline
#include <fmt/format.h>
#include <gmsh.h>
#include <mpi.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "core/comm.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/local_mesh.hpp"
#include "validation/bench/bench_cli.hpp"

namespace {

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kB
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A 25 mm x 100 mm pipe meshed by Gmsh (written once, then reused).
void write_pipe_mesh(const std::string& file, double size) {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::model::add("bench_pipe");
  const int volume = gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, 0.1, 0.0125);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair surfaces;
  gmsh::model::getBoundary({{3, volume}}, surfaces, false, false, false);
  std::vector<int> tags;
  for (const auto& s : surfaces) tags.push_back(s.second);
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, tags), "wall");
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "fluid");
  gmsh::option::setNumber("Mesh.MeshSizeMin", size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::model::mesh::generate(3);
  gmsh::option::setNumber("Mesh.Binary", 1);
  gmsh::write(file);
  gmsh::finalize();
}

}  // namespace

int main(int argc, char** argv) {
  namespace bench = valsalva::bench;
  double target = 0.00065;
  std::string file;
  bench::App app{"bench_mesh_pipeline",
                 "Time to read a Gmsh tetrahedral pipe, compute the median-dual metrics and "
                 "partition it, and peak memory per node"};
  app.add_option("--target-size", target,
                 "Gmsh mesh size of the 25 mm x 100 mm pipe [m] (0.00065: about 1 M cells)")
      ->check(bench::positive);
  app.add_option("--mesh", file,
                 "Mesh file, written by Gmsh first if it does not exist (default: "
                 "bench_pipe_<target-size>.msh)")
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {  // read, or written into an existing folder
            const auto folder = std::filesystem::path(name).parent_path();
            if (std::filesystem::exists(name) || folder.empty() ||
                std::filesystem::is_directory(folder))
              return {};
            return "folder " + folder.string() + " does not exist";
          },
          "FILE"));
  return bench::mpi_main(app, argc, argv, [&](int rank, int size) {
    if (file.empty()) file = fmt::format("bench_pipe_{:.6f}.msh", target);
    if (rank == 0 && !std::filesystem::exists(file)) {
      const auto t0 = std::chrono::steady_clock::now();
      write_pipe_mesh(file, target);
      fmt::print("gmsh meshing (not timed below): {:.1f} s -> {}\n", since(t0), file);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    const double rss0 = peak_rss_mb();
    auto t0 = std::chrono::steady_clock::now();
    const auto mesh = valsalva::mesh::read_gmsh(file);
    const double t_read = since(t0);
    t0 = std::chrono::steady_clock::now();
    const auto metrics = valsalva::mesh::compute_dual_metrics(mesh);
    const double t_metrics = since(t0);
    t0 = std::chrono::steady_clock::now();
    const auto local = valsalva::mesh::distribute(mesh, metrics, MPI_COMM_WORLD,
                                                  {2, valsalva::mesh::PartitionMethod::metis});
    const double t_partition = since(t0);
    const double rss_max = valsalva::core::Comm(MPI_COMM_WORLD).max(peak_rss_mb());
    if (rank == 0) {
      const double nodes = static_cast<double>(metrics.num_nodes());
      fmt::print("ranks {} | cells {} | nodes {} | edges {}\n", size, mesh.num_cells(),
                 metrics.num_nodes(), metrics.edges.size());
      fmt::print("read {:.2f} s | metrics {:.2f} s | partition+distribute {:.2f} s\n", t_read,
                 t_metrics, t_partition);
      fmt::print("peak RSS per rank {:.0f} MB (before reading {:.0f} MB): {:.0f} bytes per node\n",
                 rss_max, rss0, (rss_max - rss0) * 1048576.0 / nodes);
    }
  });
}
