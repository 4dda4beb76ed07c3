// The analysis sections of a scene ([probe.<name>], [probes], [sample.<name>],
// [statistics.<name>], [wall_shear], [pressure_drop.<name>]): the reader that goes with
// declare_analysis_keys (scene/scene_keys_analysis.cpp).
#pragma once

#include "analysis/analysis_options.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

namespace valsalva::scene {

// Throws SceneError naming the key for names that are not [A-Za-z0-9_]+, wall_shear patches
// that are not walls of the scene, degenerate lines, planes and boxes.
analysis::AnalysisOptions read_analysis_options(const Scene& scene, const mesh::Mesh& mesh);

// Shared by the analysis readers: a real3 key as a vector, and a table name check (names become
// file names and CSV columns) that throws SceneError on <table>.<name> unless [A-Za-z0-9_]+.
Eigen::Vector3d scene_vector(const Scene& scene, const std::string& key);
void check_plain_name(const Scene& scene, const std::string& table, const std::string& name);

}  // namespace valsalva::scene
