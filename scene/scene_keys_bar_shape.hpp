// Shape keys of a generated bar ([structure.<name>] with mesh = "bar"): the clamped end (node set
// u0) conformed to a cylinder's arc (root_arc_radius, root_arc_centre: the Turek-Hron bar glued
// to its cylinder) and a parabolic seed bend of the start positions (initial_bend).
#pragma once

#include <Eigen/Core>
#include <string>

#include "scene/scene.hpp"
#include "scene/scene_keys.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::scene {

// Declares <k>.root_arc_radius, <k>.root_arc_centre and <k>.initial_bend (k = "structure.<name>").
void declare_bar_shape_keys(Schema& s, const std::string& k);

// Before placement (the bar's own frame, origin and size as given): moves the end x = origin.x
// onto the circle of root_arc_radius about root_arc_centre (in x, y), each node at fraction
// s = (x - origin.x) / length of the way from the arc x0(y) = cx + sqrt(r^2 - (y - cy)^2) to the
// tip x = origin.x + length. Nothing when the radius is 0. Throws SceneError naming the key when
// the bar is not within the circle's height or the arc reaches past the tip.
void conform_bar_root(const Scene& scene, const std::string& k, structure::SolidMesh& mesh);

// The seed bend in the bar's own frame (before placement), 3 x nodes, or empty when
// initial_bend = 0: dy = initial_bend * s^2, s = max(0, (x - x_root) / (x_tip - x_root)), x_root
// the smallest x of node set u0 and x_tip the largest x of the mesh.
Eigen::Matrix3Xd bar_bend(const Scene& scene, const std::string& k,
                          const structure::SolidMesh& mesh);

}  // namespace valsalva::scene
