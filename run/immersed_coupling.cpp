#include "run/immersed_coupling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace valsalva::run {

ImmersedCoupling build_immersed_coupling(const scene::ImmersedSetup& setup,
                                         mesh::LocalMesh& local) {
  ImmersedCoupling c;
  c.structure = std::make_unique<ibm::ImmersedStructure>(local, setup.options);
  auto& ib = *c.structure;
  for (const auto& s : setup.structures) ib.add_body(s.mesh, *s.material, s.body);
  // Bodies released from a deformed shape (initial_stretch) start there; the bound below is
  // evaluated on it, where the stretched solid is stiffest.
  if (std::any_of(setup.structures.begin(), setup.structures.end(),
                  [](const scene::StructureSetup& s) { return s.initial.size() > 0; })) {
    Eigen::Matrix3Xd x = ib.positions();
    for (int b = 0; b < ib.num_bodies(); ++b) {
      const auto& s = setup.structures[b];
      if (s.initial.size() > 0) x.middleCols(ib.first_marker(b), s.initial.cols()) = s.initial;
    }
    ib.set_positions(x);
  }
  try {
    c.dt_bound = setup.dt_safety * ib.stable_time_step();
  } catch (const std::exception& e) {
    std::string ranges;
    for (int b = 0; b < ib.num_bodies(); ++b)
      ranges += fmt::format("{}'{}' markers {}..{}", b ? ", " : "", ib.body(b).spec().name,
                            ib.first_marker(b), ib.first_marker(b) + ib.body(b).num_nodes() - 1);
    throw std::runtime_error(fmt::format("immersed structures ({}): {}", ranges, e.what()));
  }
  return c;
}

}  // namespace valsalva::run
