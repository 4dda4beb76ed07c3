// A uniform body force along a direction d that holds the volume flux through a named section at
// a target Q(t) (forcing.type = "flow_rate"): the "constant flow rate" drive of periodic channel
// and pipe simulations (Kim, Moin & Moser, J. Fluid Mech. 177, 133-166, 1987, ran their channel
// at a constant mass flux with the mean pressure gradient adjusted every step; the variants and
// their equivalence are discussed by Quadrio, Frohnapfel & Hasegawa, Eur. J. Mech. B/Fluids 55,
// 286-293, 2016). The step is taken with the force f^n of the previous step; the predicted flux
// Q* through the section then misses Q(t^{n+1}), and the force is corrected so that it does not:
//   f^{n+1} = f^n + rho du / dt,   u^{n+1} = u* + du m,   F^{n+1}_e = F*_e + du S_e . (m_j + m_k)/2
// with m = the unit field d with the velocity boundary conditions imposed (0 on no-slip walls,
// the tangential part on slip walls) and du = (Q(t^{n+1}) - Q*) / r, r the section flux of the
// unit correction's face flux. The section flux is linear in the face flux, so Q^{n+1} equals
// the target to round-off after every step; the force is the one that, applied over the step as
// the explicit part of an Euler update (u += dt f / rho on the free nodes), gives that
// correction, as OpenFOAM's meanVelocityForce does with its rAU. The correction's face flux is
// divergence-free at every node whose neighbours are all free (sum_k S_jk = 0 there); next to a
// no-slip wall of a mesh that is not translation invariant along d it leaves a divergence of
// order du / h, which the next step's projection removes (du -> 0 as the flow settles).
// Domains closed by walls and periodic pairs only: with inlets or outlets the flux is theirs.
#pragma once

#include <functional>
#include <vector>

#include "flow/body_forcing.hpp"
#include "flow/boundary_conditions.hpp"
#include "flow/face_flux.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

class FlowRateControl {
 public:
  // Collective: the volume flux (m^3/s, along the section's normal) of a face flux on every
  // local edge, the same value on every rank (analysis::SectionFlux::flux).
  using SectionFlux = std::function<double(const EdgeField&)>;

  // `boundary`: the run's conditions (null when every patch is periodic). Collective. Throws
  // std::invalid_argument when the section is (nearly) parallel to the direction, so that no
  // correction moves its flux.
  FlowRateControl(const mesh::LocalMesh& local, BoundaryConditions* boundary,
                  const ForcingSpec& spec, SectionFlux section_flux);

  // The force density held over the next step, N/m^3 (along the direction).
  double force() const { return force_; }
  const Eigen::Vector3d& direction() const { return direction_; }
  double target(double t) const { return spec_.flow_rate(t); }
  // The section flux of the unit correction (m^2): the free part of the section's area.
  double response() const { return response_; }

  // After a step of `dt` that ended at `time`: du = (Q(time) - Q*) / r added to the velocity and
  // face flux (every local node and edge), the force updated. Collective.
  void correct(VectorField& velocity, EdgeField& face_flux, double dt, double rho, double time);

  // The state a restart needs (the force): for checkpoints.
  std::vector<double> saved() const { return {force_}; }
  void restore(const std::vector<double>& saved);

 private:
  const mesh::LocalMesh& local_;
  ForcingSpec spec_;
  SectionFlux section_flux_;
  Eigen::Vector3d direction_;
  VectorField mask_;
  EdgeField unit_flux_;
  double response_ = 0, force_ = 0;
};

}  // namespace valsalva::flow
