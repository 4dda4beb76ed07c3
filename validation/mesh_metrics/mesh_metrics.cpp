// Mesh metrics verification: on every supported cell type (structured, perturbed, periodic,
// mixed, and a Gmsh tetrahedral pipe), at the current rank count, the distributed median-dual
// metrics satisfy the identities the finite-volume scheme rests on:
//   sum of owned dual volumes = mesh volume (sum of cell volumes)         (relative 1e-12)
//   sum_k S_jk + sum A_j = 0 for every owned dual volume                  (relative to h^2, 1e-12)
//   corrected Green-Gauss gradient of a linear field exact at every node  (relative 1e-10)
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>

#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/metric_identities.hpp"
#include "mesh/pipe_generator.hpp"
#include "validation/case.hpp"

namespace valsalva::validation {

namespace {

struct Identities {
  double volume_error, closure_error, gradient_error;
  std::int64_t nodes;
};

Identities check_identities(const mesh::Mesh& mesh, MPI_Comm comm) {
  const auto metrics = mesh::compute_dual_metrics(mesh);
  const auto local = mesh::distribute(mesh, metrics, comm, {2, mesh::PartitionMethod::metis});
  const auto id = mesh::measure_metric_identities(local, mesh::mesh_volume(mesh));
  return {id.volume_error, id.closure_error, id.gradient_error, metrics.num_nodes()};
}

void run(const Context& ctx, Report& report) {
  const int n = ctx.quick ? 6 : 16;
  struct Named {
    std::string name;
    mesh::Mesh mesh;
  };
  std::vector<Named> meshes;
  for (std::string type : {"hexa", "tetra", "prism", "pyramid", "mixed"}) {
    mesh::BoxSpec spec;
    spec.cells = {n + 2, n, n - 1};
    spec.cell_type = mesh::parse_box_cell_type(type);
    meshes.push_back({type, mesh::generate_box(spec)});
    spec.periodic = {false, true, true};
    meshes.push_back({type + "_periodic_yz", mesh::generate_box(spec)});
  }
  mesh::BoxSpec perturbed;
  perturbed.cells = {n, n, n};
  perturbed.cell_type = mesh::BoxCellType::tetra;
  perturbed.perturbation = 0.2;
  meshes.push_back({"tetra_perturbed_20pct", mesh::generate_box(perturbed)});
  perturbed.periodic = {true, true, true};
  meshes.push_back({"tetra_perturbed_20pct_periodic_xyz", mesh::generate_box(perturbed)});
  meshes.push_back(
      {"gmsh_pipe", mesh::generate_pipe_mesh(0.0125, 0.05, ctx.quick ? 0.004 : 0.002)});

  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::unique_ptr<fmt::ostream> csv;
  if (rank == 0) {
    csv =
        std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "identities.csv").string()));
    csv->print("mesh,nodes,volume_error,closure_error,gradient_error\n");
  }
  for (const auto& m : meshes) {
    const auto id = check_identities(m.mesh, ctx.comm);
    report.add(m.name + ": dual volume sum rel. error", id.volume_error, 0.0, 1e-12,
               Check::at_most);
    report.add(m.name + ": max dual closure / h^2", id.closure_error, 0.0, 1e-12, Check::at_most);
    report.add(m.name + ": linear gradient rel. error", id.gradient_error, 0.0, 1e-10,
               Check::at_most);
    if (csv)
      csv->print("{},{},{:.6e},{:.6e},{:.6e}\n", m.name, id.nodes, id.volume_error,
                 id.closure_error, id.gradient_error);
  }
}

}  // namespace

Case mesh_metrics_case() {
  return {"mesh_metrics",
          "median-dual identities (volume sum, closure, exact linear gradients) on all cell types",
          run};
}

}  // namespace valsalva::validation
