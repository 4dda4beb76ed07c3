// Mesh metrics verification: on every supported cell type (structured, perturbed, periodic,
// mixed, and a Gmsh tetrahedral pipe), at the current rank count, the distributed median-dual
// metrics satisfy the identities the finite-volume scheme rests on:
//   sum of owned dual volumes = mesh volume (sum of cell volumes)         (relative 1e-12)
//   sum_k S_jk + sum A_j = 0 for every owned dual volume                  (relative to h^2, 1e-12)
//   corrected Green-Gauss gradient of a linear field exact at every node  (relative 1e-10)
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>

#include "flow/compensated_sum.hpp"
#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "io/box_generator.hpp"
#include "io/pipe_generator.hpp"
#include "validation/case.hpp"

namespace valsalva::validation {

namespace {

struct Identities {
  double volume_error, closure_error, gradient_error;
  std::int64_t nodes;
};

Identities check_identities(const flow::Mesh& mesh, MPI_Comm comm) {
  const auto metrics = flow::compute_dual_metrics(mesh);
  const auto local = flow::distribute(mesh, metrics, comm, {2, "metis"});
  flow::CompensatedSum owned_volume;
  for (int i = 0; i < local.num_owned; ++i) owned_volume.add(local.volume[i]);
  const double reference = flow::mesh_volume(mesh);
  const double volume_error = std::abs(local.comm.sum(owned_volume.value()) - reference) / reference;

  const Eigen::Vector3d g(0.3, -1.1, 2.4);
  std::vector<Eigen::Vector3d> closure(local.num_local(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> raw(local.num_local(), Eigen::Vector3d::Zero());
  for (int e = 0; e < local.num_owned_edges; ++e) {
    const auto [a, b] = local.edges[e];
    closure[a] += local.edge_normal[e];
    closure[b] -= local.edge_normal[e];
    const double dphi = g.dot(local.edge_vector[e]);
    raw[a] += 0.5 * dphi * local.edge_normal[e];
    raw[b] += 0.5 * dphi * local.edge_normal[e];
  }
  for (const auto& f : local.boundary) closure[f.node] += f.area;
  double closure_error = 0, gradient_error = 0;
  for (int i = 0; i < local.num_owned; ++i) {
    closure_error = std::max(closure_error, closure[i].norm() / (local.h[i] * local.h[i]));
    const Eigen::Vector3d grad = local.gradient_correction[i] * raw[i] / local.volume[i];
    gradient_error = std::max(gradient_error, (grad - g).norm() / g.norm());
  }
  return {volume_error, local.comm.max(closure_error), local.comm.max(gradient_error),
          metrics.num_nodes()};
}

void run(const Context& ctx, Report& report) {
  const int n = ctx.quick ? 6 : 16;
  struct Named {
    std::string name;
    flow::Mesh mesh;
  };
  std::vector<Named> meshes;
  for (std::string type : {"hexa", "tetra", "prism", "pyramid", "mixed"}) {
    io::BoxSpec spec;
    spec.cells = {n + 2, n, n - 1};
    spec.cell_type = type;
    meshes.push_back({type, io::generate_box(spec)});
    spec.periodic = {false, true, true};
    meshes.push_back({type + "_periodic_yz", io::generate_box(spec)});
  }
  io::BoxSpec perturbed;
  perturbed.cells = {n, n, n};
  perturbed.cell_type = "tetra";
  perturbed.perturbation = 0.2;
  meshes.push_back({"tetra_perturbed_20pct", io::generate_box(perturbed)});
  perturbed.periodic = {true, true, true};
  meshes.push_back({"tetra_perturbed_20pct_periodic_xyz", io::generate_box(perturbed)});
  meshes.push_back({"gmsh_pipe", io::generate_pipe_mesh(0.0125, 0.05, ctx.quick ? 0.004 : 0.002)});

  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::unique_ptr<fmt::ostream> csv;
  if (rank == 0) {
    csv = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "identities.csv").string()));
    csv->print("mesh,nodes,volume_error,closure_error,gradient_error\n");
  }
  for (const auto& m : meshes) {
    const auto id = check_identities(m.mesh, ctx.comm);
    report.add(m.name + ": dual volume sum rel. error", id.volume_error, 0.0, 1e-12, Check::at_most);
    report.add(m.name + ": max dual closure / h^2", id.closure_error, 0.0, 1e-12, Check::at_most);
    report.add(m.name + ": linear gradient rel. error", id.gradient_error, 0.0, 1e-10, Check::at_most);
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
