// The scene of the case validation/womersley at one level (womersley.toml: the extruded disk;
// womersley_delaunay.toml: Gmsh's 3D Delaunay tetrahedra) and its overrides, shared with
// bench_womersley_study and test_rank_agreement (validation/bench/womersley_run.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace valsalva::validation {

struct WomersleyLevel {
  double womersley = 17;
  double nodes_per_diameter = 20;  // h = D / nodes_per_diameter
  double length_in_diameters = 2;
  bool extruded = false;                   // womersley.toml, else womersley_delaunay.toml
  std::string outlet = "pressure_outlet";  // boundary.outlet.type
  std::string les_model = "none";          // les.model
  int sample_period = 3;                   // time.end = (sample_period + 1) periods
  double dt = 0;                           // time.dt
  double poisson_tolerance = 1e-10;        // poisson.tolerance
  int max_steps = 0;                       // time.max_steps (0: none)
  bool stiffness_viscous = false;          // flow.viscous_weights = stiffness
  double mesh_size_factor = 1;             // mesh size = factor * h
  // Extruded only (mesh.extruded_pipe.*), in units of the mesh size.
  double layer_height = 1, wall_size = 0, wall_distance = 0;
  double layer_first = 0, layer_ratio = 1.2, layer_thickness = 0;
};

// The pipe radius of a Womersley number (rho 1100, mu 3.6e-3, T = 1 s), m.
double womersley_radius(double womersley);

std::filesystem::path womersley_scene(const WomersleyLevel& level);

// Mesh, the exact start, the inlet Q0 (1 + sin(2 pi t / T)) with Q0 = (5 D / T) pi R^2, the
// outlet, the model, the solver options and the step.
std::vector<std::string> womersley_overrides(const WomersleyLevel& level);

}  // namespace valsalva::validation
