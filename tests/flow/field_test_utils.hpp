// Helpers shared by the flow operator, Poisson and Taylor-Green tests: build a distributed box
// mesh, gather owned nodal values into the partition-independent dual-node order (to compare
// np = 1 with np = N), volume-weighted norms and observed orders.
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "flow/operators.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/pipe_generator.hpp"

namespace valsalva::test {

// The meshes of the order-of-accuracy tests: uniform hexahedra and split tetrahedra (order
// asserted) and tetrahedra perturbed by 20% of h (order reported).
struct MeshKind {
  std::string type;
  double perturbation;
  bool asserted;
};
inline std::vector<MeshKind> order_mesh_kinds() {
  return {{"hexa", 0.0, true}, {"tetra", 0.0, true}, {"tetra", 0.2, false}};
}

inline mesh::BoxSpec periodic_box(const std::string& type, int n, double perturbation = 0.0) {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::parse_box_cell_type(type);
  spec.cells = {n, n, n};
  spec.perturbation = perturbation;
  spec.periodic = {true, true, true};
  return spec;
}

// The meshes of the energy tests: uniform hexahedra, split and 20 % perturbed tetrahedra,
// prisms (optional) and a Gmsh Delaunay bent pipe.
struct NamedMesh {
  std::string name;
  mesh::Mesh mesh;
};
inline std::vector<NamedMesh> energy_meshes(bool with_prisms) {
  std::vector<NamedMesh> out;
  out.push_back({"hexa", mesh::generate_box(periodic_box("hexa", 6))});
  out.push_back({"split tetra", mesh::generate_box(periodic_box("tetra", 6))});
  out.push_back({"perturbed tetra", mesh::generate_box(periodic_box("tetra", 6, 0.2))});
  if (with_prisms) out.push_back({"prism", mesh::generate_box(periodic_box("prism", 6))});
  out.push_back(
      {"gmsh bent pipe", mesh::generate_bent_pipe_mesh(0.5, 1.5, std::numbers::pi / 2, 0.25)});
  return out;
}

// The box `spec` distributed over `comm` with 2 ghost layers (the mesh is not kept).
inline mesh::LocalMesh local_box(const mesh::BoxSpec& spec, MPI_Comm comm = MPI_COMM_WORLD) {
  const auto mesh = mesh::generate_box(spec);
  return mesh::distribute(mesh, mesh::compute_dual_metrics(mesh), comm,
                          {2, mesh::PartitionMethod::metis});
}

// Owned values of `component`-wide nodal data, summed over ranks into dual-node order.
inline std::vector<double> gather_by_dual_node(const mesh::LocalMesh& mesh,
                                               const std::vector<double>& values, int components,
                                               mesh::GlobalIndex global_nodes) {
  std::vector<double> out(static_cast<std::size_t>(global_nodes * components), 0.0);
  for (int i = 0; i < mesh.num_owned; ++i)
    for (int c = 0; c < components; ++c)
      out[mesh.dual_node[i] * components + c] = values[i * components + c];
  MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(out.size()), MPI_DOUBLE, MPI_SUM,
                mesh.comm.get());
  return out;
}

// x, y, z of every vector in turn (for gather_by_dual_node with 3 components).
inline std::vector<double> flatten(const flow::VectorField& u) {
  std::vector<double> out;
  for (const auto& v : u) out.insert(out.end(), {v.x(), v.y(), v.z()});
  return out;
}

inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

inline double observed_order(double e_coarse, double e_fine, double h_coarse, double h_fine) {
  return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
}

}  // namespace valsalva::test
