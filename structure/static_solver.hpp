// Static equilibrium f_int(x) + lambda f_ext(x) = 0 by Newton's method with load stepping
// (adaptive: a failed increment is halved), backtracking line search on the residual norm, and a
// diagnosis when it cannot converge (inverted element, singular tangent, non-finite or
// stagnating residual). Dirichlet supports prescribe displacement components on node sets; the
// prescribed displacement is scaled by the load factor too. Frictionless contact between surface
// pairs and against rigid obstacles (structure/contact.hpp) adds its penalty forces and their
// exact, non-symmetric tangent.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "structure/contact.hpp"
#include "structure/loads.hpp"
#include "structure/solid_forces.hpp"

namespace valsalva::structure {

struct Dirichlet {
  std::vector<int> nodes;
  std::array<bool, 3> components{true, true, true};
  std::function<Vec3(const Vec3& X)> displacement;  // at load factor 1; empty means zero
};

struct PressureLoad {
  std::vector<FaceRef> faces;
  double pressure = 0;  // [Pa], follower, positive into the solid
};

struct TractionLoad {
  std::vector<FaceRef> faces;
  Vec3 traction = Vec3::Zero();  // [Pa], dead, per reference area
};

struct StaticProblem {
  const SolidForces* forces = nullptr;
  std::vector<Dirichlet> dirichlet;
  std::vector<PressureLoad> pressures;
  std::vector<TractionLoad> tractions;
  Vec3 body_force = Vec3::Zero();    // per reference volume [N/m^3]
  std::vector<ContactPair> contact;  // pairs of surfaces of different bodies
  std::vector<RigidObstacle> obstacles;
  ContactOptions contact_options;
};

struct NewtonOptions {
  int load_steps = 10;
  int max_iterations = 30;
  double rtol = 1e-9;  // residual / max(|lambda f_ext|, |reactions|)
  int max_cuts = 8;    // successive halvings of a failing increment
  bool line_search = true;
  // Pseudo-transient continuation (Kelley & Keyes, SIAM J. Numer. Anal. 35:508, 1998): each
  // increment solves f(x) - d (x - x_start) = 0 with d = damping * mean diag(K), which carries the
  // solve through limit points (snap-through of curved shells) where load control alone fails.
  // After the full load, damped relaxation steps at lambda = 1 with d halved each time continue
  // until the undamped residual converges. 0 disables it.
  double damping = 0;
  int max_relaxation_steps = 200;
  // A state test, empty = every state is admissible. A trial state it rejects is treated like
  // one with an inverted element: the line search halves the step, and an increment that cannot
  // avoid it is cut. The valve's closing uses it to refuse steps that push a leaflet through
  // another faster than the contact penalty can act (a thin body is crossed in one Newton step;
  // the filtered line search of Li et al., "Incremental Potential Contact", ACM Trans. Graph. 39
  // (2020) 49, keeps every iterate intersection-free the same way).
  std::function<bool(const Eigen::Matrix3Xd& x)> admissible;
  bool verbose = false;
};

struct NewtonResult {
  bool converged = false;
  Eigen::Matrix3Xd x;      // final positions (last converged state if not converged)
  double load_factor = 0;  // reached
  int steps = 0, iterations = 0, cuts = 0;
  std::vector<double> last_residuals;  // relative residuals of the last increment
  std::string diagnosis;               // why it failed, empty on success
  std::string solver;                  // linear solver used
  ContactSummary contact;              // at x (empty without contact)
};

NewtonResult solve_static(const StaticProblem& problem, const NewtonOptions& options,
                          const Eigen::Matrix3Xd* initial = nullptr);

}  // namespace valsalva::structure
