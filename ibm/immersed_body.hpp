// One immersed solid of the ITBM coupling: its Lagrangian hexahedral mesh, material law and the
// forces its nodes (the markers) apply to the fluid:
//   F_a(x) = F_int,a(x) - k_t (x_a - X_a) [a clamped] + F_c,a(x),
// F_c the frictionless penalty contact forces between surface pairs of the body and against rigid
// obstacles (structure/contact.hpp: the same forces as in the static solver), F_int the explicit
// internal forces of structure::SolidForces (F_a = -int P grad_X N_a dV, so
// sum_a F_int,a = 0 and the torque vanishes for objective laws) and the second term a stiff
// tether (spring of stiffness k_t [N/m] per node) holding clamped nodes at their anchors, the
// reference positions (Griffith & Luo, J. Comput. Phys. 2017, "target points"). The tether
// reaction is a force like any other: it is spread too, so the fluid feels the support.
//
// Markers are the solid's nodes (Q2: all 27 per element), not its Gauss points: the weak form
// gives forces at nodes, so spreading nodal forces keeps total force and torque exactly, and the
// interpolated velocity moves the nodes that define the finite-element geometry without a
// projection. Each marker carries the lumped reference volume V_a = int N_a dV (positive for
// Lagrange Q1/Q2: corner 1/216, edge 1/54, face 2/27, centre 8/27 of a cube's volume) and, with
// solid density rho_s, the mass rho_s V_a, which the coupling neglects (fluid fills the solid).
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "structure/contact.hpp"
#include "structure/material.hpp"
#include "structure/solid_forces.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::ibm {

// How clamped node sets are held: `tether`, a stiff spring to the reference position, the node
// staying a marker of the coupling (a clamped edge inside the fluid); `fixed`, exactly at the
// reference position (Dirichlet) and no marker at all: neither located, spread nor interpolated,
// its elastic force carried by the support (an edge clamped on a rigid wall such as a valve
// frame, where there is no fluid to couple with).
enum class Clamp { tether, fixed };

struct BodySpec {
  // A constructor (not an aggregate) so that {name, clamped_sets, tether_stiffness} stays the
  // short form without the contact fields.
  BodySpec(std::string name_ = "structure", std::vector<std::string> clamped = {},
           double tether = 0)
      : name(std::move(name_)), clamped_sets(std::move(clamped)), tether_stiffness(tether) {}
  std::string name;
  std::vector<std::string> clamped_sets;  // node sets held by the tether
  double tether_stiffness;                // k_t [N/m per node], > 0 when clamped_sets is not empty
  Clamp clamp = Clamp::tether;            // with fixed, tether_stiffness is unused
  // Contact between surfaces of this body (e.g. the leaflets of a valve, disjoint node sets of
  // one mesh) and against rigid obstacles (a root wall); empty: none.
  std::vector<structure::ContactPair> contact;
  std::vector<structure::RigidObstacle> obstacles;
  structure::ContactOptions contact_options;
};

class ImmersedBody {
 public:
  // `mesh` and `material` must outlive the body.
  ImmersedBody(const structure::SolidMesh& mesh, const structure::Material& material,
               BodySpec spec);

  // f (3 x nodes) = internal + tether + contact forces at positions x; returns the smallest
  // det F. Allocation-free without contact. Collective over the processes of share_contact.
  double forces(const Eigen::Ref<const Eigen::Matrix3Xd>& x, Eigen::Ref<Eigen::Matrix3Xd> f) const;
  // Splits the contact search of forces() over processes that all hold this body (the contact
  // is most of a closed valve's force cost): each evaluates `share`'s slave faces and `sum`
  // adds the contact forces of all shares in place, the same result on every process. The
  // internal forces stay whole on each (they are cheap). share.parts = 1: no split.
  void share_contact(structure::ContactShare share, std::function<void(std::span<double>)> sum);
  // Sum of the tether forces at x (the reaction of the supports on the solid).
  Eigen::Vector3d tether_force(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const;
  // Stiffness K = -dF/dx at x (internal tangent + k_t on tethered nodes), dof 3*node +
  // component, plus the exact tangent of the contact between surfaces at x, plus, on every node
  // of an obstacle surface, k_c I with k_c = Contact::obstacle_stiffness() whether or not it
  // touches the wall at x. Why the two differ: contact between two surfaces acts as equal and
  // opposite forces at coincident points, which the kernel spreads almost to nothing, so a pair
  // closing between two re-evaluations of the coupling's bound hardly moves it (the closed pair
  // is in the tangent at the next one); a wall's reaction is one-sided and is spread in full.
  void stiffness(const Eigen::Matrix3Xd& x, Eigen::SparseMatrix<double>& K) const;
  // The contact state at x (empty summary without contact).
  structure::ContactSummary contact_summary(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const;
  bool has_contact() const { return contact_ != nullptr; }

  const BodySpec& spec() const { return spec_; }
  const structure::SolidMesh& mesh() const { return forces_.mesh(); }
  const structure::SolidForces& solid_forces() const { return forces_; }
  int num_nodes() const { return mesh().num_nodes(); }
  const std::vector<int>& clamped_nodes() const { return clamped_; }  // sorted, unique
  // The clamped nodes when they are fixed (Clamp::fixed), else none.
  const std::vector<int>& fixed_nodes() const { return fixed_; }
  const Eigen::VectorXd& nodal_volume() const { return nodal_volume_; }
  // Largest distance between lattice-neighbour nodes of an element (the marker spacing) at x.
  double max_marker_spacing(const Eigen::Matrix3Xd& x) const;

 private:
  structure::SolidForces forces_;
  BodySpec spec_;
  std::unique_ptr<structure::Contact> contact_;
  structure::ContactShare share_;
  std::function<void(std::span<double>)> sum_shares_;
  mutable Eigen::Matrix3Xd shared_contact_force_;  // this process's share, then the sum
  Eigen::VectorXd obstacle_stiffness_;             // Contact::obstacle_stiffness()
  std::vector<int> clamped_;
  std::vector<int> fixed_;
  Eigen::VectorXd nodal_volume_;
  std::vector<std::array<int, 2>> neighbour_pairs_;  // local node pairs one lattice step apart
};

// Lumped reference volumes V_a = int N_a dV of a hexahedral mesh.
Eigen::VectorXd lumped_nodal_volume(const structure::SolidMesh& mesh);

}  // namespace valsalva::ibm
