// Frictionless contact between surface sets of one SolidMesh (separate bodies = disjoint node
// sets, e.g. the three leaflets of a valve) and against rigid analytic obstacles (plane, cylinder).
//
// Method: penalty regularisation with the normal gap evaluated at the quadrature points of each
// contact face and measured along the normal of the closest point of the opposite surface
// (Gauss-point-to-surface), in the unbiased two-half-pass form of Sauer & De Lorenzis, "A
// computational contact formulation based on surface potentials", CMAME 253 (2013) 369-395 (3D:
// Sauer & De Lorenzis, CMAME 293 (2015) 151-179): each surface of a pair is the slave once, and
// the traction p n_m, p = eps <-g>, acts on the slave's nodes only. Both halves see the same
// penalty eps, so the bodies exchange equal and opposite forces up to the discretisation; unlike
// the one-pass (master-slave) and the classical two-pass forms it passes the contact patch test
// for non-matching meshes. ContactOptions::formulation = two_pass gives the momentum-exact
// variant (each point's force and its reaction on the master) used in flow runs, where a net
// force would be spread into the fluid. Rigid obstacles use the same gap with the obstacle as
// master.
// The tangent -df/dx is exact: forward-mode automatic differentiation of the point force,
// including the closest-point projection (structure/contact_kernel.hpp). It is not symmetric.
// Penalty: eps = penalty_factor * E / h (eps of the order of the stiffness of the underlying
// elements, E / h, times a factor; Wriggers, Computational Contact Mechanics, 2nd ed. 2006), E the
// material's small-strain Young's modulus and h the mean face size of the pair;
// at a contact pressure p the penetration is p / eps = (p / E) h / penalty_factor.
// Spatial search: a core::BucketGrid over the current face centres of the master surface.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <limits>
#include <string>
#include <vector>

#include "structure/material.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::structure {

// Two contact surfaces of different bodies (no shared node). Build them from named surface sets
// with contact_surface(mesh, {"leaflet1_aortic_face", "leaflet1_ventricular_face"}).
struct ContactPair {
  std::string name;  // for reports, e.g. "leaflet1-leaflet2"
  std::vector<FaceRef> a, b;
};

// A rigid obstacle: the faces must stay on the allowed side of a plane (point, normal pointing
// into the allowed side) or inside/outside a cylinder (axis through point along direction,
// radius).
struct RigidObstacle {
  enum class Shape { plane, cylinder };
  std::string name;
  Shape shape = Shape::plane;
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();  // plane: normal; cylinder: axis
  double radius = 0;               // cylinder only
  bool inside = true;              // cylinder: the body stays inside (a vessel wall)
  std::vector<FaceRef> faces;
};

struct ContactOptions {
  // eps = penalty_factor * E / h (see the header): 100 keeps the penetration at 1 % of the face
  // size at a pressure of E / 1e4, and the penalty springs at about 100 times the stiffness of
  // the elements they act on, which direct solvers factor without loss.
  double penalty_factor = 100;
  // E [Pa]; 0: 3 G with G = dP_xy/dF_xy at F = I of the material (its small-strain shear
  // modulus; 3 G is Young's modulus of an incompressible solid).
  double modulus = 0;
  // Only closest points within search_factor * h (above or below the surface) count; deeper
  // penetration is not detected (keep load steps small enough).
  double search_factor = 1.0;
  // Width of the C1 smoothing of the penalty near g = 0, as a fraction of the face size h
  // (contact_kernel.hpp penalty_pressure); 0: the plain penalty eps <-g>. Smoothing lets Newton
  // converge where points keep entering and leaving contact (coapting leaflets).
  double smoothing = 0;
  // Clearance c [m] between the surfaces of a pair: the penalty acts on g - c, so the surfaces
  // are held about c apart instead of touching (a contact thickness offset). An immersed
  // boundary cannot separate two surfaces that lie within one fluid cell of each other (both
  // interpolate the same fluid velocity), so coapting leaflets are kept a fluid cell apart
  // (docs/valve.md, "Reopening"). Rigid obstacles ignore it.
  double clearance = 0;
  // Gauss points per direction on each slave face; 0: order + 2 (as pressure loads).
  int quadrature = 0;
  // two_half_pass (the header): passes the patch test; the two bodies' forces are equal and
  // opposite only up to the discretisation (the halves integrate different gaps on different
  // faces). two_pass: each half applies half its traction to the slave and the reaction to the
  // master nodes at the closest point (N_b there), so every Gauss point's forces cancel exactly
  // (no net force, which the immersed boundary would spread into the fluid), at the price of
  // the patch test (the master-side forces are integrated at the other surface's points).
  enum class Formulation { two_half_pass, two_pass };
  Formulation formulation = Formulation::two_half_pass;
  // Projects every slave point on every master face, without the broad phase (boxes, spheres)
  // or the projection's early exit outside the face: the reference the fast search must equal
  // (tests; far too slow for a run).
  bool exhaustive_search = false;
};

// Result of one evaluation, per pair (two-half-pass pairs: both halves together) or obstacle.
struct ContactSurfaceSummary {
  std::string name;
  double penalty = 0;  // eps [Pa/m]
  double h = 0;        // face size used for eps [m]
  // Smallest signed gap over the Gauss points whose closest point lies within the search radius
  // (negative: penetration); +inf when none does.
  double min_gap = std::numeric_limits<double>::infinity();
  int min_gap_node = -1;           // slave face node nearest to that Gauss point
  FaceRef min_gap_face{-1, -1};    // its slave face
  FaceRef min_gap_master{-1, -1};  // the master face it projects on (-1 for an obstacle)
  double force = 0;                // normal contact force int p da [N] (two halves: their mean)
  double area = 0;                 // current area where p > 0 [m^2] (two halves: their mean)
  double max_pressure = 0;         // [Pa]
  int active_points = 0;
};

struct ContactSummary {
  std::vector<ContactSurfaceSummary> surfaces;
  double min_gap = std::numeric_limits<double>::infinity();  // over all surfaces
  double force = 0, area = 0, max_pressure = 0;              // sums / max over all surfaces
  // Work of the evaluation (benchmarks): slave Gauss points searched, closest-point projections
  // (Newton solves) run for them, and the Newton iterations of those.
  long slave_points = 0, projections = 0, newton_iterations = 0;
};

// One slave Gauss point with a closest point within the search radius (for plots and tests).
struct ContactPoint {
  int surface = 0;  // index into ContactSummary::surfaces
  int half = 0;     // 0: slave a (or the obstacle's faces), 1: slave b
  FaceRef face;
  Vec3 x = Vec3::Zero();  // current position
  double gap = 0, pressure = 0, area = 0;
};

// Faces of the named surface sets, concatenated (throws naming a missing set).
std::vector<FaceRef> contact_surface(const SolidMesh& mesh, const std::vector<std::string>& sets);

// One pair between every two of the bodies, each given by its surface sets; named
// "<first set of i>-<first set of j>". For a valve: {{"leaflet1_aortic_face",
// "leaflet1_ventricular_face"}, {"leaflet2_...", ...}, {"leaflet3_...", ...}} gives the three
// leaflet-leaflet pairs.
std::vector<ContactPair> pairs_between(const SolidMesh& mesh,
                                       const std::vector<std::vector<std::string>>& bodies);

// E for the penalty: 3 dP_xy/dF_xy at F = I.
double small_strain_modulus(const Material& material);

// The part of the slave faces one process evaluates: faces part, part + parts, part + 2 parts,
// ... in the order of the pairs, halves and obstacles (round robin), so that ranks that all hold
// the whole structure can split the contact search and sum their forces.
struct ContactShare {
  int part = 0, parts = 1;
};

class Contact {
 public:
  // Throws, naming the pair, if a pair's surfaces share a node or a surface is empty.
  Contact(const SolidMesh& mesh, const Material& material, std::vector<ContactPair> pairs,
          std::vector<RigidObstacle> obstacles, const ContactOptions& options);

  bool empty() const { return pairs_.empty() && obstacles_.empty(); }
  // Adds the contact forces (acting on the nodes, like SolidForces' internal forces) to f; when
  // K is given, appends the tangent -df/dx as triplets (dof 3 * node + component). With a
  // share, only the forces (and summary) of that share's slave faces.
  // Allocates (search grid, candidate lists).
  ContactSummary add_forces(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                            Eigen::Ref<Eigen::Matrix3Xd> f,
                            std::vector<Eigen::Triplet<double>>* K = nullptr,
                            ContactShare share = {}) const;
  // The summary alone (no forces).
  ContactSummary summary(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const;
  std::vector<ContactPoint> points(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const;
  // Per node: eps times its share int N_a dA of the reference area of the obstacle surfaces it
  // is on [N/m] (the row sum of the tangent of a fully active, flat contact with a rigid wall:
  // what a closing wall contact can add to a node's stiffness, for explicit time-step bounds).
  Eigen::VectorXd obstacle_stiffness() const;

 private:
  const SolidMesh& mesh_;
  std::vector<ContactPair> pairs_;
  std::vector<RigidObstacle> obstacles_;
  ContactOptions options_;
  double modulus_ = 0;
  std::vector<double> h_;  // per pair, then per obstacle
  template <int NF>
  ContactSummary evaluate(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                          Eigen::Ref<Eigen::Matrix3Xd>* f, std::vector<Eigen::Triplet<double>>* K,
                          std::vector<ContactPoint>* pts, ContactShare share = {}) const;
};

}  // namespace valsalva::structure
