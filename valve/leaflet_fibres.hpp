// Fibre axes that follow each leaflet: for the Holzapfel–Gasser–Ogden law (structure/material.hpp,
// fibres a = cos(gamma) e1 +- sin(gamma) e2) every element gets its own e1 = the leaflet's
// circumferential direction and e2 = its radial direction (from the attachment towards the free
// edge, in the leaflet surface), instead of the global x and y of a single HgoParameters. The
// axes come from the element's reference tangents at its centre: e2 = dX/deta (normalised) and
// e1 = the part of dX/dxi normal to it. valve/leaflet_mesh.hpp builds leaflets with xi along the
// arc and eta along the cylinder's generators (so e1 = e_theta, e2 = e_z exactly on the open
// leaflets, also near the slanted scallop), and this holds for the open leaflets and for any mesh
// with the same connectivity (a closed leaflet used as the stress-free reference).
#pragma once

#include <memory>
#include <vector>

#include "structure/material.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::valve {

struct FibreAxes {
  structure::Vec3 circumferential, radial;  // unit, orthogonal
};

// One pair per element, from the reference coordinates X of `mesh`.
std::vector<FibreAxes> leaflet_fibre_axes(const structure::SolidMesh& mesh);

// HGO laws with p's constants and each element's axes (p.e1, p.e2 are replaced); hand
// element_pointers(...) to structure::SolidForces's per-element constructor.
std::vector<std::unique_ptr<structure::Material>> hgo_per_element(
    const structure::HgoParameters& p, const std::vector<FibreAxes>& axes);
std::vector<const structure::Material*> element_pointers(
    const std::vector<std::unique_ptr<structure::Material>>& materials);

}  // namespace valsalva::valve
