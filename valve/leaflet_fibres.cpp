#include "valve/leaflet_fibres.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace valsalva::valve {

using structure::Mat3;
using structure::Vec3;

std::vector<FibreAxes> leaflet_fibre_axes(const structure::SolidMesh& mesh) {
  const int nen = mesh.nodes_per_element();
  std::vector<double> N(nen), dN(3 * nen);
  structure::hex_shape(mesh.order, Vec3::Zero(), N, dN);
  std::vector<FibreAxes> axes(mesh.num_elements());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    Mat3 J = Mat3::Zero();  // dX/dxi at the element centre
    for (int a = 0; a < nen; ++a)
      for (int k = 0; k < 3; ++k) J.col(k) += mesh.X.col(mesh.element_nodes(e)[a]) * dN[3 * a + k];
    const Vec3 radial = J.col(1).normalized();
    const Vec3 t1 = J.col(0) - J.col(0).dot(radial) * radial;
    if (!(t1.norm() > 1e-12 * J.col(0).norm()) || !radial.allFinite())
      throw std::invalid_argument(fmt::format(
          "{}: element {} is degenerate, its fibre axes are undefined", mesh.source, e));
    axes[e] = {t1.normalized(), radial};
  }
  return axes;
}

std::vector<std::unique_ptr<structure::Material>> hgo_per_element(
    const structure::HgoParameters& p, const std::vector<FibreAxes>& axes) {
  std::vector<std::unique_ptr<structure::Material>> out;
  out.reserve(axes.size());
  for (const FibreAxes& a : axes) {
    structure::HgoParameters q = p;
    q.e1 = a.circumferential;
    q.e2 = a.radial;
    out.push_back(structure::make_hgo(q));
  }
  return out;
}

std::vector<const structure::Material*> element_pointers(
    const std::vector<std::unique_ptr<structure::Material>>& materials) {
  std::vector<const structure::Material*> out;
  for (const auto& m : materials) out.push_back(m.get());
  return out;
}

}  // namespace valsalva::valve
