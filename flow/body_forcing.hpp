// A prescribed body-force density of a run ([forcing] in a scene), for flows driven without
// inlets: a uniform force (a periodic pipe or channel under a mean pressure gradient G: F = -G),
// constant or with a time dependence (a sine about a mean, or a table factor), or Kolmogorov's
// sinusoidal force F sin(2 pi s / lambda), s = x . across (a periodic box kept in a laminar or
// turbulent state; the stability case). It is added to the force of immersed structures, when
// there are any, at every RK stage. A force that holds a flow rate (type flow_rate) is set by
// flow/flow_rate_control.hpp.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "flow/inflow_waveform.hpp"
#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

struct ForcingSpec {
  enum class Type { none, uniform, kolmogorov, flow_rate };
  Type type = Type::none;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // N/m^3: F (kolmogorov: amplitude)
  Eigen::Vector3d across = Eigen::Vector3d::UnitY();  // kolmogorov: direction of variation
  double wavelength = 1;                              // kolmogorov: m
  // uniform: F(t) = force (constant); force + amplitude sin(2 pi t / period + phase) (sine);
  // force * s(t) with s(t) the table (table).
  Waveform::Kind waveform = Waveform::Kind::constant;
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();  // N/m^3 (sine)
  double period = 1, phase = 0;                         // s, rad (sine)
  Waveform factor;                                      // table: s(t), dimensionless
  // flow_rate: the force along `direction` (normalised) that holds the flux through the section
  // named `section` at the target Q(t) (m^3/s, Waveform's constant, sine or table).
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  std::string section;
  Waveform flow_rate;

  // The uniform force density at time t (type uniform).
  Eigen::Vector3d uniform_force(double t) const;
  // True when the force density changes with time (uniform with a waveform, flow_rate).
  bool time_dependent() const;
};

// The force density at every local node at t = 0 (flow_rate: zero, the controller's start).
// Kolmogorov's force has zero mean, but its samples at the nodes of an irregular mesh do not
// (1.5e-4 F on 20 % perturbed tetrahedra), and a periodic box has nothing that removes the
// momentum a net force puts in: the discrete (volume-weighted) mean is subtracted. Collective.
VectorField forcing_density(const mesh::LocalMesh& local, const ForcingSpec& spec);

}  // namespace valsalva::flow
