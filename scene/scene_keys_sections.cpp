// Scene keys of the section fluxes: [section.<name>] (a plane, optionally bounded to one cut of
// the mesh) and [sections] (how often sections.csv gets a row).
#include "scene/scene_keys_sections.hpp"

#include "scene/scene_keys.hpp"
#include "scene/scene_keys_analysis.hpp"

namespace valsalva::scene {

void declare_section_keys(Schema& s) {
  const std::string k = "section.<name>";
  s.section(
      k,
      "Volume flux Q (m^3/s) through an interior section: the sum of the solver's projected "
      "dual-face fluxes over the mesh edges that cross the plane (analysis/section_flux.hpp), "
      "which equals the inflow through a complete cross-section to the Poisson tolerance. "
      "One column <name>_flux in sections.csv; the run log gives the edges cut and the "
      "last values.");
  s.real3(k + ".point").required().unit_of("m").doc("A point of the plane (the disc's centre)");
  s.real3(k + ".normal")
      .required()
      .unit_of("-")
      .doc("Normal of the plane; Q is positive along it (any length > 0)");
  s.choice(k + ".bound", {"none", "disc", "box"})
      .def("none")
      .unit_of("-")
      .doc(
          "Which part of the plane: all of it, a disc about point, or the part in an "
          "axis-aligned box (to pick one cut where the plane crosses the mesh more than once)");
  s.real(k + ".radius")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Disc radius; make it a little larger than the vessel to take the whole cut");
  s.when(k + ".radius", k + ".bound", {"disc"});
  s.real3(k + ".lo").required().unit_of("m").doc("Lower corner of the box");
  s.when(k + ".lo", k + ".bound", {"box"});
  s.real3(k + ".hi").required().unit_of("m").doc("Upper corner of the box");
  s.when(k + ".hi", k + ".bound", {"box"});

  s.section("sections", "When the section fluxes are evaluated (one row of sections.csv).");
  s.integer("sections.every_steps")
      .def(1)
      .at_least(1)
      .unit_of("-")
      .doc("Evaluate the section fluxes every this many time steps");
}

analysis::SectionsOptions read_section_options(const Scene& scene) {
  analysis::SectionsOptions o;
  for (const auto& name : scene.names("section")) {
    check_plain_name(scene, "section", name);
    const std::string k = "section." + name;
    analysis::SectionOptions s;
    s.name = name;
    s.point = scene_vector(scene, k + ".point");
    s.normal = scene_vector(scene, k + ".normal");
    if (!(s.normal.norm() > 0)) throw scene.error(k + ".normal", "the normal is zero");
    const auto bound = scene.get<std::string>(k + ".bound");
    if (bound == "disc") {
      s.bound = analysis::SectionOptions::Bound::disc;
      s.radius = scene.get<double>(k + ".radius");
    } else if (bound == "box") {
      s.bound = analysis::SectionOptions::Bound::box;
      s.lo = scene_vector(scene, k + ".lo");
      s.hi = scene_vector(scene, k + ".hi");
      if (!(s.lo.array() < s.hi.array()).all())
        throw scene.error(k + ".hi",
                          "the box's upper corner must exceed its lower corner in x, y and z");
    }
    o.sections.push_back(s);
  }
  o.every_steps = scene.get<int>("sections.every_steps");
  return o;
}

}  // namespace valsalva::scene
