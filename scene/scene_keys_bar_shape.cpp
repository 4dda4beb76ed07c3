// Shape keys of a generated bar; see scene_keys_bar_shape.hpp.
#include "scene/scene_keys_bar_shape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace valsalva::scene {

void declare_bar_shape_keys(Schema& s, const std::string& k) {
  s.real(k + ".root_arc_radius")
      .def(0.0)
      .at_least(0)
      .unit_of("m")
      .doc(
          "Radius of a cylinder (axis along z through root_arc_centre) that the bar's end x = "
          "origin.x (node set u0) follows: each node moves to fraction (x - origin.x) / length of "
          "the way from the arc x0(y) = cx + sqrt(r^2 - (y - cy)^2) to the tip x = origin.x + "
          "length, in the bar's frame before rotation and translation (the Turek-Hron bar glued "
          "to its cylinder); 0 = a straight end");
  s.real3(k + ".root_arc_centre")
      .def(std::array{0.0, 0.0, 0.0})
      .unit_of("m")
      .doc("Centre of that cylinder (x and y; z is ignored)");
  s.real(k + ".initial_bend")
      .unit_of("m")
      .def(0.0)
      .doc(
          "The markers start bent by dy = initial_bend * s^2, s = max(0, (x - x_root) / (x_tip - "
          "x_root)) with x_root the smallest x of node set u0 and x_tip the largest x of the bar "
          "(in its frame before placement): a seed that starts flutter (Turek-Hron FSI3); the "
          "mesh stays the stress-free reference; not with initial_stretch");
  for (const char* key : {".root_arc_radius", ".root_arc_centre", ".initial_bend"})
    s.when(k + key, k + ".mesh", {"bar"});
}

void conform_bar_root(const Scene& scene, const std::string& k, structure::SolidMesh& mesh) {
  const double r = scene.get<double>(k + ".root_arc_radius");
  if (r == 0) return;
  const auto c = scene.get<std::array<double, 3>>(k + ".root_arc_centre");
  const auto origin = scene.get<std::array<double, 3>>(k + ".origin");
  const double length = scene.get<std::array<double, 3>>(k + ".size")[0];
  const double tip = origin[0] + length;
  for (int a = 0; a < mesh.num_nodes(); ++a) {
    const double dy = mesh.X(1, a) - c[1];
    if (!(std::abs(dy) < r))
      throw scene.error(k + ".root_arc_radius",
                        fmt::format("the bar reaches y = {:g}, beyond the arc of radius {:g} "
                                    "about y = {:g}",
                                    mesh.X(1, a), r, c[1]));
    const double x0 = c[0] + std::sqrt(r * r - dy * dy);
    if (!(x0 < tip))
      throw scene.error(
          k + ".root_arc_radius",
          fmt::format("the arc reaches x = {:g}, past the bar's tip x = {:g}", x0, tip));
    const double s = (mesh.X(0, a) - origin[0]) / length;
    mesh.X(0, a) = x0 + s * (tip - x0);
  }
}

Eigen::Matrix3Xd bar_bend(const Scene& scene, const std::string& k,
                          const structure::SolidMesh& mesh) {
  const double bend = scene.get<double>(k + ".initial_bend");
  if (bend == 0) return {};
  const auto stretch = scene.get<std::array<double, 3>>(k + ".initial_stretch");
  if (stretch != std::array{1.0, 1.0, 1.0})
    throw scene.error(k + ".initial_bend", "initial_bend and initial_stretch exclude each other");
  double root = 1e300;
  for (int a : mesh.node_set("u0")) root = std::min(root, mesh.X(0, a));
  const double tip = mesh.X.row(0).maxCoeff();
  Eigen::Matrix3Xd d = Eigen::Matrix3Xd::Zero(3, mesh.num_nodes());
  for (int a = 0; a < mesh.num_nodes(); ++a) {
    const double s = std::max(0.0, (mesh.X(0, a) - root) / (tip - root));
    d(1, a) = bend * s * s;
  }
  return d;
}

}  // namespace valsalva::scene
