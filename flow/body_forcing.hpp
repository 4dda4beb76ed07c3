// A prescribed body-force density of a run ([forcing] in a scene), for flows driven without
// inlets: a uniform force (a periodic pipe or channel under a mean pressure gradient G: F = -G)
// or Kolmogorov's sinusoidal force F sin(2 pi s / lambda), s = x . across (a periodic box kept
// in a laminar or turbulent state; the stability case). It is added to the force of immersed
// structures, when there are any, at every RK stage.
#pragma once

#include <Eigen/Dense>

#include "flow/local_mesh.hpp"
#include "flow/operators.hpp"

namespace valsalva::flow {

struct ForcingSpec {
  enum class Type { none, uniform, kolmogorov };
  Type type = Type::none;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // N/m^3: F (kolmogorov: amplitude)
  Eigen::Vector3d across = Eigen::Vector3d::UnitY();  // kolmogorov: direction of variation
  double wavelength = 1;                              // kolmogorov: m
};

// The force density at every local node. Kolmogorov's force has zero mean, but its samples at
// the nodes of an irregular mesh do not (1.5e-4 F on 20 % perturbed tetrahedra), and a periodic
// box has nothing that removes the momentum a net force puts in: the discrete (volume-weighted)
// mean is subtracted. Collective.
VectorField forcing_density(const LocalMesh& local, const ForcingSpec& spec);

}  // namespace valsalva::flow
