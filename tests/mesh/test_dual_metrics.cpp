// Median-dual metrics: volumes add up to the mesh volume, every dual volume closes, and the
// corrected Green-Gauss gradient of a linear field is exact at every node, on every box cell
// type, perturbed or not, periodic or not.
#include <doctest/doctest.h>

#include <cmath>

#include "core/compensated_sum.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/dual_metrics.hpp"

using namespace valsalva;

namespace {

struct Closure {
  double max_interior = 0;  // max |sum S + sum A| / (area scale), over all nodes
};

double max_closure(const mesh::DualMetrics& m) {
  std::vector<Eigen::Vector3d> sum(m.num_nodes(), Eigen::Vector3d::Zero());
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    sum[m.edges[e][0]] += m.edge_normal[e];
    sum[m.edges[e][1]] -= m.edge_normal[e];
  }
  for (const auto& b : m.boundary) sum[b.node] += b.area;
  double worst = 0;
  for (mesh::GlobalIndex j = 0; j < m.num_nodes(); ++j)
    worst = std::max(worst, sum[j].norm() / (m.h[j] * m.h[j]));
  return worst;
}

double max_gradient_error(const mesh::DualMetrics& m, const Eigen::Vector3d& g) {
  std::vector<Eigen::Vector3d> raw(m.num_nodes(), Eigen::Vector3d::Zero());
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const double dphi = g.dot(m.edge_vector[e]);  // phi_k - phi_j for phi = g.x
    raw[m.edges[e][0]] += 0.5 * dphi * m.edge_normal[e];
    raw[m.edges[e][1]] += 0.5 * dphi * m.edge_normal[e];
  }
  double worst = 0;
  for (mesh::GlobalIndex j = 0; j < m.num_nodes(); ++j) {
    const Eigen::Vector3d grad = m.gradient_correction[j] * (raw[j] / m.volume[j]);
    worst = std::max(worst, (grad - g).norm() / g.norm());
  }
  return worst;
}

}  // namespace

TEST_CASE("dual metrics on box meshes of every cell type") {
  for (std::string type : {"hexa", "tetra", "prism", "pyramid", "mixed"}) {
    for (double perturbation : {0.0, 0.2}) {
      for (bool periodic : {false, true}) {
        mesh::BoxSpec spec;
        spec.cell_type = mesh::parse_box_cell_type(type);
        spec.cells = {8, 5, 4};
        spec.length = Eigen::Vector3d(1.0, 0.7, 0.5);
        spec.perturbation = perturbation;
        spec.periodic = {periodic && type != "mixed", false, periodic};  // mixed: x ends differ
        CAPTURE(type);
        CAPTURE(perturbation);
        CAPTURE(periodic);
        const auto mesh = mesh::generate_box(spec);
        const auto m = mesh::compute_dual_metrics(mesh);
        core::CompensatedSum sum;
        for (double v : m.volume) sum.add(v);
        const double total = sum.value();
        CHECK(std::abs(total - 0.35) / 0.35 < 1e-12);
        CHECK(std::abs(mesh::mesh_volume(mesh) - 0.35) / 0.35 < 1e-12);
        CHECK(max_closure(m) < 1e-12);
        CHECK(max_gradient_error(m, Eigen::Vector3d(1.3, -0.4, 2.1)) < 1e-10);
      }
    }
  }
}
