#include "scene/mesh_source.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "core/allocation_limit.hpp"
#include "mesh/box_generator.hpp"
#include "mesh/cylinder_channel_generator.hpp"
#include "mesh/extruded_pipe_generator.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/periodic_pipe_generator.hpp"
#include "mesh/pipe_generator.hpp"

namespace valsalva::scene {

namespace {
constexpr double min_mesh_span = 1e-6, max_mesh_span = 1e4;  // m
}  // namespace

namespace {

mesh::BoxSpec box_spec(const Scene& scene) {
  mesh::BoxSpec spec;
  const auto origin = scene.get<std::array<double, 3>>("mesh.box.origin");
  const auto length = scene.get<std::array<double, 3>>("mesh.box.length");
  spec.origin = Eigen::Vector3d(origin[0], origin[1], origin[2]);
  spec.length = Eigen::Vector3d(length[0], length[1], length[2]);
  spec.cells = scene.get<std::array<int, 3>>("mesh.box.cells");
  // Each hexahedron holds at least a node (24 bytes), 8 node indices (64), an offset, a type and
  // a region (13), before any split into other cell types or the dual metrics.
  const auto& c = spec.cells;
  if (const auto problem = core::allocation_problem(
          fmt::format("[{}, {}, {}] cells", c[0], c[1], c[2]), double(c[0]) * c[1] * c[2], 101);
      !problem.empty())
    throw scene.error("mesh.box.cells", problem);
  spec.cell_type = mesh::parse_box_cell_type(scene.get<std::string>("mesh.box.cell_type"));
  spec.perturbation = scene.get<double>("mesh.box.perturbation");
  spec.seed = static_cast<std::uint64_t>(scene.get<std::int64_t>("mesh.box.seed"));
  for (const auto& axis : scene.get<std::vector<std::string>>("mesh.box.periodic"))
    spec.periodic[axis[0] - 'x'] = true;
  return spec;
}

// A mesh in several pieces (cells sharing no node, periodic pairs aside) is a mistake: each piece
// has its own pressure null space and the Poisson solve fails far from the cause.
}  // namespace

std::string disconnected_pieces(const mesh::Mesh& mesh) {
  std::vector<mesh::GlobalIndex> parent(static_cast<std::size_t>(mesh.num_nodes()));
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<mesh::GlobalIndex>(i);
  auto root = [&](mesh::GlobalIndex n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    for (std::size_t k = 1; k < nodes.size(); ++k) parent[root(nodes[k])] = root(nodes[0]);
  }
  std::vector<mesh::GlobalIndex> first_cell;  // one cell of each piece
  std::vector<mesh::GlobalIndex> seen;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) {
    const auto r = root(mesh.cell(c)[0]);
    if (std::find(seen.begin(), seen.end(), r) == seen.end()) {
      seen.push_back(r);
      first_cell.push_back(c);
      if (seen.size() > 8) break;
    }
  }
  if (first_cell.size() < 2) return {};
  return fmt::format("mesh '{}' is in {}{} disconnected pieces (one cell of each: {})", mesh.source,
                     first_cell.size() > 8 ? "more than " : "",
                     std::min<std::size_t>(first_cell.size(), 8), fmt::join(first_cell, ", "));
}

namespace {}  // namespace

mesh::Mesh build_mesh(const Scene& scene, MPI_Comm comm) {
  const std::string source = scene.get<std::string>("mesh.source");
  mesh::Mesh mesh;
  if (source == "box") {
    try {
      mesh = mesh::generate_box(box_spec(scene));
    } catch (const std::invalid_argument& e) {
      throw scene.error("mesh.box", e.what());
    }
  } else if (source == "gmsh") {
    const auto file = scene.path("mesh.file");
    if (!std::filesystem::exists(file))
      throw scene.error("mesh.file", fmt::format("file '{}' does not exist", file.string()));
    mesh = mesh::read_gmsh(file);
  } else if (source == "cylinder_channel") {
    const std::string k = "mesh.cylinder_channel.";
    mesh::CylinderChannelSpec spec;
    spec.size_near = scene.get<double>(k + "size_near");
    spec.size_far = scene.get<double>(k + "size_far");
    spec.grading_distance = scene.get<double>(k + "grading_distance");
    spec.thickness = scene.get<double>(k + "thickness");
    spec.layers = scene.get<int>(k + "layers");
    spec.length = scene.get<double>(k + "length");
    spec.height = scene.get<double>(k + "height");
    spec.diameter = scene.get<double>(k + "diameter");
    spec.centre_x = scene.get<double>(k + "centre_x");
    spec.centre_y = scene.get<double>(k + "centre_y");
    spec.split = scene.get<std::string>(k + "cells") == "tetra";
    spec.box_size = scene.get<double>(k + "box_size");
    spec.box_x0 = scene.get<double>(k + "box_x0");
    spec.box_x1 = scene.get<double>(k + "box_x1");
    spec.box_y0 = scene.get<double>(k + "box_y0");
    spec.box_y1 = scene.get<double>(k + "box_y1");
    spec.box_transition = scene.get<double>(k + "box_transition");
    try {
      mesh = mesh::generate_cylinder_channel_mesh(spec);
    } catch (const std::invalid_argument& e) {
      throw scene.error("mesh.cylinder_channel", e.what());
    }
  } else if (source == "extruded_pipe") {
    const std::string k = "mesh.extruded_pipe.";
    mesh::ExtrudedPipeSpec spec;
    spec.radius = scene.get<double>(k + "radius");
    spec.length = scene.get<double>(k + "length");
    spec.target_size = scene.get<double>(k + "size");
    spec.layer_height = scene.get<double>(k + "layer_height");
    spec.grading.wall_size = scene.get<double>(k + "wall_size");
    spec.grading.wall_distance = scene.get<double>(k + "wall_distance");
    spec.grading.layer_first = scene.get<double>(k + "layer_first");
    spec.grading.layer_ratio = scene.get<double>(k + "layer_ratio");
    spec.grading.layer_thickness = scene.get<double>(k + "layer_thickness");
    try {
      mesh = mesh::generate_extruded_pipe_mesh(spec, comm);
    } catch (const std::invalid_argument& e) {
      throw scene.error("mesh.extruded_pipe", e.what());
    }
  } else if (source == "periodic_pipe") {
    const std::string k = "mesh.periodic_pipe.";
    mesh::PeriodicPipeSpec spec;
    spec.radius = scene.get<double>(k + "radius");
    spec.length = scene.get<double>(k + "length");
    spec.target_size = scene.get<double>(k + "size");
    spec.layers = scene.get<int>(k + "layers");
    spec.split = scene.get<std::string>(k + "cells") == "tetra";
    try {
      mesh = mesh::generate_periodic_pipe_mesh(spec);
    } catch (const std::invalid_argument& e) {
      throw scene.error("mesh.periodic_pipe", e.what());
    }
  } else {
    mesh = mesh::generate_pipe_mesh(scene.get<double>("mesh.pipe.radius"),
                                    scene.get<double>("mesh.pipe.length"),
                                    scene.get<double>("mesh.pipe.size"));
  }
  const double scale = scene.get<double>("mesh.scale");
  if (scale != 1.0) {
    for (auto& x : mesh.nodes) x *= scale;
    // A generator's periodic pairs are in the mesh's units too (a scaled periodic box used to be
    // refused: its translations no longer matched the nodes).
    for (auto& link : mesh.periodic) link.translation *= scale;
  }

  // SI units: a mesh a micrometre across or of ten kilometres is a unit mistake, and far below that
  // the dual-face metrics underflow (a box of 1e-200 m failed inside the Poisson weights).
  if (!mesh.nodes.empty()) {
    Eigen::Vector3d lo = mesh.nodes.front(), hi = lo;
    for (const auto& x : mesh.nodes) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    const double span = (hi - lo).lpNorm<Eigen::Infinity>();  // no underflow, unlike norm()
    if (!(span >= min_mesh_span && span <= max_mesh_span))
      throw scene.error(
          scale != 1.0 ? "mesh.scale" : "mesh.source",
          fmt::format("the mesh spans {:.3g} m (largest bounding-box side): valsalva "
                      "works in SI units (mesh.scale converts a mesh drawn in mm)",
                      span),
          fmt::format("a mesh spanning [{:g}, {:g}] m", min_mesh_span, max_mesh_span));
  }

  for (const auto& pair : scene.names("mesh.periodic")) {
    const std::string prefix = "mesh.periodic." + pair;
    mesh::PeriodicLink link;
    link.master = scene.get<std::string>(prefix + ".master");
    link.slave = scene.get<std::string>(prefix + ".slave");
    const auto t = scene.get<std::array<double, 3>>(prefix + ".translation");
    link.translation = Eigen::Vector3d(t[0], t[1], t[2]);
    for (const auto& [key, patch] :
         {std::pair{".master", link.master}, std::pair{".slave", link.slave}})
      if (mesh.patch_index(patch) < 0)
        throw scene.error(prefix + key, fmt::format("patch '{}' is not in the mesh", patch),
                          fmt::format("{}", fmt::join(mesh.patch_names, ", ")));
    mesh.periodic.push_back(link);
  }
  mesh::check_mesh(mesh);
  if (const auto pieces = disconnected_pieces(mesh); !pieces.empty())
    throw scene.error("mesh.source", pieces, "one connected mesh");
  return mesh;
}

}  // namespace valsalva::scene
